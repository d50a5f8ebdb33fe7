// Writes the fuzzer's seed corpus into the directory given: for every packet kind, a filled
// sample (tests/unit/serialization/sample_packets.hpp) and a default one, each prefixed with the
// byte that selects the packet decoder. Starting from valid encodings lets the fuzzer reach
// the inside of every kind instead of first guessing its layout.
#include "decoders.hpp"
#include "unit/serialization/sample_packets.hpp"
#include <cstdint>
#include <cstdio>
#include <string>
#include <variant>
#include <vector>

namespace {

bool write_seed(const std::string &path, std::uint8_t decoder, const std::vector<std::uint8_t> &bytes) {
    auto *file = std::fopen(path.c_str(), "wb");
    if (!file) return false;
    auto ok =
        std::fputc(decoder, file) != EOF && std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
    return std::fclose(file) == 0 && ok;
}

} // namespace

int main(int argc, char **argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s CORPUS_DIRECTORY\n", argv[0]);
        return 2;
    }
    const std::string directory = argv[1];
    constexpr std::uint8_t packet_decoder = 0;
    int written = 0;
    auto samples = edyn::test::sample_packets();
    for (std::size_t kind = 0; kind < samples.size(); ++kind) {
        auto defaults = samples[kind];
        std::visit([](auto &p) { p = std::remove_cvref_t<decltype(p)>{}; }, defaults.var);
        auto stem = directory + "/" + edyn::fuzz::decoders[packet_decoder].name + "-" + std::to_string(kind);
        if (!write_seed(stem + "-sample", packet_decoder, edyn::fuzz::encode(samples[kind])) ||
            !write_seed(stem + "-default", packet_decoder, edyn::fuzz::encode(defaults))) {
            std::fprintf(stderr, "could not write seeds into %s\n", directory.c_str());
            return 1;
        }
        written += 2;
    }
    std::printf("wrote %d seeds into %s\n", written, directory.c_str());
    return 0;
}
