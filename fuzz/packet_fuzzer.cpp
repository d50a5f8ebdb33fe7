// libFuzzer entry point for the decoders of decoders.hpp, built by scripts/fuzz.sh with clang,
// AddressSanitizer and UndefinedBehaviorSanitizer: a crash, an over-read, an undefined operation
// or a failed re-encoding check aborts, and libFuzzer keeps the input.
#include "decoders.hpp"
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <span>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    if (size == 0) return 0;
    constexpr auto count = std::size(edyn::fuzz::decoders);
    auto &decoder = edyn::fuzz::decoders[data[0] % count];
    decoder.check(std::span<const std::uint8_t>(data + 1, size - 1));
    return 0;
}
