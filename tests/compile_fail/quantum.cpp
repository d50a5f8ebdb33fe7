// Compiled (not run) by the quantize.* tests of tests/CMakeLists.txt: serialize_quantized must
// build with a constant quantum and refuse, at compile time, one that is not positive and finite.
#include "edyn/serialization/memory_archive.hpp"
#include "edyn/serialization/quantize.hpp"
#include <cstdint>
#include <limits>
#include <vector>

int main() {
    std::vector<std::uint8_t> data;
    edyn::memory_output_archive archive(data);
    auto v = edyn::vector3_zero;
    edyn::serialize_quantized(archive, v, EDYN_TEST_QUANTUM);
    return int(data.size() == 0);
}
