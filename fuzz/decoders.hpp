#ifndef EDYN_FUZZ_DECODERS_HPP
#define EDYN_FUZZ_DECODERS_HPP

// The formats the fuzzer decodes. An input's first byte picks one (modulo their number) and the
// rest is given to it, so one fuzzer and one corpus cover all of them; new decoders are
// appended, so that the seeds of the existing ones keep selecting them.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <edyn/networking/packet/edyn_packet.hpp>
#include <edyn/serialization/memory_archive.hpp>
#include <span>
#include <vector>

namespace edyn::fuzz {

struct decoder {
    const char *name;
    void (*check)(std::span<const std::uint8_t> bytes);
};

template<typename T>
std::vector<std::uint8_t> encode(const T &value) {
    std::vector<std::uint8_t> data;
    memory_output_archive archive(data);
    archive(value);
    return data;
}

[[noreturn]] inline void report(const char *name, const char *what, std::size_t size) {
    std::fprintf(stderr, "%s: %s (input of %zu bytes)\n", name, what, size);
    std::abort();
}

// Whatever decodes must describe a value completely: its encoding decodes again, to a value
// whose encoding is the same bytes. (The input itself need not be canonical: LEB128 allows
// redundant bytes, and bytes after the value are not read.)
// `Use`, when given, is what the program does first with a decoded value: it must cope with
// anything that decodes.
template<typename T, const char *Name, void (*Use)(const T &) = nullptr>
void check_reencoding(std::span<const std::uint8_t> bytes) {
    T value{};
    memory_input_archive input(bytes.data(), bytes.size());
    input(value);
    if (input.failed()) return;
    if constexpr (Use != nullptr) Use(value);

    auto first = encode(value);
    T again{};
    memory_input_archive second(first.data(), first.size());
    second(again);
    if (second.failed()) report(Name, "its own encoding does not decode", bytes.size());
    if (second.remaining() != 0) report(Name, "its own encoding decodes with bytes left over", bytes.size());
    if (encode(again) != first) report(Name, "re-encoding gives different bytes", bytes.size());
}

inline constexpr char edyn_packet_name[] = "edyn_packet";

inline void use_packet(const packet::edyn_packet &packet) {
    // Which channel it would be answered on; the result is not checked, only that it copes.
    [[maybe_unused]] volatile bool reliable = should_send_reliably(packet);
}

// Decoders of components for registry snapshots (they need a registry) go here when they come.
inline constexpr decoder decoders[] = {
    {edyn_packet_name, &check_reencoding<packet::edyn_packet, edyn_packet_name, &use_packet>},
};

} // namespace edyn::fuzz

#endif // EDYN_FUZZ_DECODERS_HPP
