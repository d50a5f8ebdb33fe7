// Quantised vectors and orientations (quantize.hpp): error bounds, clamping, NaN, byte sizes,
// and bytes from anyone (values past the bound, crafted orientation bits).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <edyn/serialization/memory_archive.hpp>
#include <edyn/serialization/quantize.hpp>
#include <gtest/gtest.h>
#include <limits>
#include <random>
#include <type_traits>
#include <vector>

using namespace edyn;

namespace {

// The bound quantize.hpp derives for smallest three on 15 bits, 4·√3·(√2 / 32767 / 2) ≈ 0.00015
// to first order, with room for the second-order terms and float rounding.
constexpr double max_angle_error = 0.00016;

std::vector<std::uint8_t> encode_quantized(vector3 v, quantum_step quantum) {
    std::vector<std::uint8_t> data;
    memory_output_archive archive(data);
    serialize_quantized(archive, v, quantum);
    return data;
}

vector3 decode_quantized(const std::vector<std::uint8_t> &data, quantum_step quantum, bool *ok = nullptr) {
    memory_input_archive archive(data.data(), data.size());
    auto v = vector3{-1, -1, -1};
    serialize_quantized(archive, v, quantum);
    EXPECT_EQ(archive.remaining(), 0u);
    if (ok) *ok = !archive.failed();
    return v;
}

vector3 round_trip_quantized(vector3 v, quantum_step quantum) {
    bool ok = false;
    auto result = decode_quantized(encode_quantized(v, quantum), quantum, &ok);
    EXPECT_TRUE(ok);
    return result;
}

// The angle of the rotation that takes one unit quaternion to the other, in double so that
// the measurement is not limited by float: 4 asin(|a - b| / 2) with b on a's side.
double angle_between(const quaternion &a, const quaternion &b) {
    double d = 0;
    for (int i = 0; i < 4; ++i)
        d += double(a[i]) * double(b[i]);
    double sign = d < 0 ? -1 : 1;
    double distance = 0;
    for (int i = 0; i < 4; ++i) {
        auto delta = double(a[i]) - sign * double(b[i]);
        distance += delta * delta;
    }
    return 4 * std::asin(std::min(1.0, std::sqrt(distance) / 2));
}

double unit_error(const quaternion &q) {
    double sum = 0;
    for (int i = 0; i < 4; ++i)
        sum += double(q[i]) * double(q[i]);
    return std::abs(std::sqrt(sum) - 1);
}

quaternion random_rotation(std::mt19937 &rng) {
    std::normal_distribution<double> normal;
    double c[4], sum = 0;
    do {
        sum = 0;
        for (auto &x : c) {
            x = normal(rng);
            sum += x * x;
        }
    } while (sum < 1e-6);
    auto len = std::sqrt(sum);
    return {scalar(c[0] / len), scalar(c[1] / len), scalar(c[2] / len), scalar(c[3] / len)};
}

void check_round_trip_error(quantum_step step, scalar range, const char *what) {
    const auto quantum = step.value;
    std::mt19937 rng(1234);
    std::uniform_real_distribution<scalar> uniform(-range, range);
    // Also magnitudes spread over many octaves, where float's own spacing changes.
    std::uniform_real_distribution<double> exponent(-12, std::log2(double(range)));
    scalar worst = 0;
    for (int i = 0; i < 100000; ++i) {
        vector3 v;
        for (int j = 0; j < 3; ++j) {
            v[j] = (i & 1) ? uniform(rng) : scalar(std::exp2(exponent(rng))) * (rng() & 1 ? 1 : -1);
        }
        auto result = round_trip_quantized(v, step);
        for (int j = 0; j < 3; ++j) {
            auto error = std::abs(result[j] - v[j]);
            worst = std::max(worst, error);
            ASSERT_LE(error, quantum / 2) << what << " " << v[j] << " came back as " << result[j];
        }
    }
    std::printf("%s: largest round-trip error %g (quantum %g)\n", what, double(worst), double(quantum));
}

TEST(quantize, position_error_is_at_most_half_a_quantum) {
    check_round_trip_error(position_quantum, max_quantized_coordinate, "positions");
    check_round_trip_error(position_quantum, 100, "positions near the origin");
}

TEST(quantize, velocity_error_is_at_most_half_a_quantum) {
    check_round_trip_error(velocity_quantum, 200, "velocities");
}

TEST(quantize, multiples_of_the_quantum_are_exact) {
    auto v = vector3{position_quantum * 3, -position_quantum * 1000001, max_quantized_coordinate};
    EXPECT_EQ(round_trip_quantized(v, position_quantum), v);
}

TEST(quantize, values_beyond_the_bound_clamp) {
    auto inf = std::numeric_limits<scalar>::infinity();
    auto beyond = vector3{max_quantized_coordinate * 3, -inf, std::numeric_limits<scalar>::max()};
    auto result = round_trip_quantized(beyond, position_quantum);
    EXPECT_EQ(result,
              (vector3{max_quantized_coordinate, -max_quantized_coordinate, max_quantized_coordinate}))
        << "got " << result.x << " " << result.y << " " << result.z;
    auto velocity = round_trip_quantized({inf, -std::numeric_limits<scalar>::max(), 1e30f}, velocity_quantum);
    EXPECT_EQ(velocity,
              (vector3{max_quantized_coordinate, -max_quantized_coordinate, max_quantized_coordinate}));
}

TEST(quantize, nan_encodes_as_zero) {
    auto nan = std::numeric_limits<scalar>::quiet_NaN();
    auto result = round_trip_quantized({nan, 1, -nan}, position_quantum);
    EXPECT_EQ(result, (vector3{0, 1, 0})) << "got " << result.x << " " << result.y << " " << result.z;
}

TEST(quantize, byte_sizes) {
    EXPECT_EQ(encode_quantized(vector3_zero, position_quantum).size(), 3u);
    std::mt19937 rng(99);
    std::uniform_real_distribution<scalar> direction(-1, 1);
    std::size_t largest = 0;
    for (int i = 0; i < 10000; ++i) {
        auto v = vector3{direction(rng), direction(rng), direction(rng)};
        auto len = length(v);
        if (len < scalar(0.01)) continue;
        // Magnitude just under 8 m.
        v = v * (scalar(7.99) / len);
        largest = std::max(largest, encode_quantized(v, position_quantum).size());
        largest = std::max(largest, encode_quantized(v * 2, velocity_quantum).size());
    }
    std::printf("a position under 8 m (a velocity under 16 m/s) takes at most %zu bytes\n", largest);
    EXPECT_LE(largest, 6u);
    EXPECT_EQ(encode_quantized({1000, -1000, 1023}, position_quantum).size(), 9u);
    auto far = vector3{max_quantized_coordinate, -max_quantized_coordinate, max_quantized_coordinate};
    EXPECT_EQ(encode_quantized(far, position_quantum).size(), 15u);
}

// serialize_quantized(archive, v, 0) and a quantum known only at run time do not compile: a
// quantum_step is made from a constant, checked when it is compiled.
template<typename T>
concept quantum_from_scalar = std::is_convertible_v<T, quantum_step>;

TEST(quantize, the_quantum_is_a_checked_compile_time_constant) {
    static_assert(!std::is_default_constructible_v<quantum_step>);
    static_assert(quantum_from_scalar<scalar>, "constants convert implicitly");
    constexpr quantum_step position = position_quantum, velocity = velocity_quantum, custom = scalar(0.125);
    EXPECT_EQ(position.value, position_quantum);
    EXPECT_EQ(velocity.value, velocity_quantum);
    EXPECT_EQ(custom.value, scalar(0.125));
    EXPECT_EQ(round_trip_quantized({scalar(0.25), -1, 3}, custom), (vector3{scalar(0.25), -1, 3}));
}

TEST(quantize, a_value_past_the_bound_fails) {
    auto max_steps = std::uint64_t(max_quantized_coordinate / position_quantum);
    for (auto [encoded, ok] : {std::pair{2 * max_steps, true}, std::pair{2 * max_steps - 1, true},
                               std::pair{2 * max_steps + 1, false}, std::pair{~std::uint64_t{0}, false}}) {
        std::vector<std::uint8_t> data;
        memory_output_archive output(data);
        output.write_varint(0);
        output.write_varint(encoded);
        output.write_varint(0);
        memory_input_archive input(data.data(), data.size());
        auto v = vector3{7, 7, 7};
        serialize_quantized(input, v, position_quantum);
        EXPECT_EQ(!input.failed(), ok) << "zig-zag value " << encoded;
        if (ok) {
            EXPECT_EQ(std::abs(v.y), max_quantized_coordinate) << "zig-zag value " << encoded;
        } else {
            EXPECT_EQ(v, (vector3{7, 7, 7})) << "a failed read changed the vector";
        }
    }
}

TEST(quantize, truncated_vector_fails_untouched) {
    auto data = encode_quantized({100, -200, 300}, position_quantum);
    for (std::size_t size = 0; size < data.size(); ++size) {
        memory_input_archive input(data.data(), size);
        auto v = vector3{7, 7, 7};
        serialize_quantized(input, v, position_quantum);
        EXPECT_TRUE(input.failed()) << size << " of " << data.size() << " bytes";
        EXPECT_EQ(v, (vector3{7, 7, 7}));
    }
}

TEST(quantize, orientation_precision) {
    std::mt19937 rng(42);
    double worst = 0, total = 0, worst_unit = 0;
    constexpr int count = 100000;
    for (int i = 0; i < count; ++i) {
        auto q = random_rotation(rng);
        auto result = unpack_orientation(pack_orientation(q));
        auto angle = angle_between(q, result);
        worst = std::max(worst, angle);
        total += angle;
        worst_unit = std::max(worst_unit, unit_error(result));
    }
    std::printf(
        "smallest three: largest angle error %.6f rad (%.4f deg), mean %.6f rad, largest |len - 1| %g\n",
        worst, worst * 180 / 3.14159265358979, total / count, worst_unit);
    EXPECT_LT(worst, max_angle_error) << "largest angle error";
    EXPECT_LT(worst_unit, 1e-6);
}

TEST(quantize, each_component_can_be_the_largest) {
    for (int largest = 0; largest < 4; ++largest) {
        for (scalar sign : {scalar(1), scalar(-1)}) {
            quaternion q{scalar(0.1), scalar(-0.2), scalar(0.3), scalar(-0.15)};
            q[largest] = sign * scalar(0.9);
            q = normalize(q);
            auto bits = pack_orientation(q);
            EXPECT_EQ(int(bits >> 45), largest);
            auto result = unpack_orientation(bits);
            EXPECT_GT(result[largest], 0) << "the dropped component decodes positive";
            EXPECT_LT(angle_between(q, result), max_angle_error)
                << "largest component " << largest << " sign " << sign;
        }
    }
}

TEST(quantize, q_and_minus_q_encode_alike) {
    std::mt19937 rng(7);
    for (int i = 0; i < 10000; ++i) {
        auto q = random_rotation(rng);
        ASSERT_EQ(pack_orientation(q), pack_orientation(-q)) << "iteration " << i;
    }
    EXPECT_EQ(pack_orientation(quaternion_identity), pack_orientation(-quaternion_identity));
    // Ties: equal magnitudes choose the first.
    auto tie = normalize(quaternion{1, -1, 1, -1});
    EXPECT_EQ(pack_orientation(tie) >> 45, 0u);
    EXPECT_LT(angle_between(unpack_orientation(pack_orientation(tie)), tie), max_angle_error);
}

TEST(quantize, non_unit_input_is_normalised) {
    auto q = normalize(quaternion{scalar(0.3), scalar(0.4), scalar(-0.5), scalar(0.6)});
    for (scalar scale : {scalar(3), scalar(1e-20), scalar(1e30), scalar(-0.5)}) {
        auto scaled = quaternion{q.x * scale, q.y * scale, q.z * scale, q.w * scale};
        auto result = unpack_orientation(pack_orientation(scaled));
        EXPECT_LT(angle_between(q, result), max_angle_error) << "scale " << scale;
    }
    auto max = std::numeric_limits<scalar>::max();
    EXPECT_LT(angle_between(unpack_orientation(pack_orientation({max, max, 0, 0})),
                            normalize(quaternion{1, 1, 0, 0})),
              max_angle_error);
}

TEST(quantize, degenerate_input_is_identity) {
    auto nan = std::numeric_limits<scalar>::quiet_NaN();
    auto inf = std::numeric_limits<scalar>::infinity();
    for (auto q : {quaternion{0, 0, 0, 0}, quaternion{nan, 0, 0, 1}, quaternion{0, 0, inf, 1},
                   quaternion{nan, nan, nan, nan}, quaternion{-inf, inf, 0, 0}}) {
        auto result = unpack_orientation(pack_orientation(q));
        EXPECT_LT(angle_between(result, quaternion_identity), max_angle_error)
            << "got " << result.x << " " << result.y << " " << result.z << " " << result.w;
    }
}

TEST(quantize, any_bits_decode_to_a_unit_quaternion) {
    constexpr std::uint64_t all = (std::uint64_t{1} << 48) - 1;
    std::vector<std::uint64_t> bits{0,
                                    all,
                                    all >> 1,
                                    std::uint64_t{1} << 45,
                                    std::uint64_t{1} << 47,
                                    (std::uint64_t{1} << 45) - 1,
                                    ~std::uint64_t{0}};
    // Every index with every component at either extreme or the middle.
    for (std::uint64_t index = 0; index < 4; ++index) {
        for (std::uint64_t a : {0u, 16383u, 16384u, 32767u}) {
            for (std::uint64_t b : {0u, 16383u, 16384u, 32767u}) {
                for (std::uint64_t c : {0u, 16383u, 16384u, 32767u})
                    bits.push_back(index << 45 | a << 30 | b << 15 | c);
            }
        }
    }
    // And about a million spread over the whole range (an odd stride).
    for (std::uint64_t k = 0; k <= all; k += 281474977)
        bits.push_back(k);

    double worst = 0;
    for (auto b : bits) {
        auto q = unpack_orientation(b);
        auto error = unit_error(q);
        worst = std::max(worst, error);
        ASSERT_TRUE(std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z) && std::isfinite(q.w))
            << "bits " << b;
        ASSERT_LT(error, 1e-6) << "bits " << b;
    }
    std::printf("%zu crafted bit patterns: largest |len - 1| %g\n", bits.size(), worst);
}

TEST(quantize, serialized_orientation_takes_six_bytes) {
    auto q = normalize(quaternion{scalar(0.1), scalar(0.7), scalar(-0.2), scalar(0.5)});
    std::vector<std::uint8_t> data;
    memory_output_archive output(data);
    serialize_quantized(output, q);
    ASSERT_EQ(data.size(), 6u);

    memory_input_archive input(data.data(), data.size());
    auto result = quaternion_identity;
    serialize_quantized(input, result);
    EXPECT_FALSE(input.failed());
    EXPECT_LT(angle_between(q, result), max_angle_error);

    for (std::size_t size : {3u, 5u}) {
        memory_input_archive truncated(data.data(), size);
        auto kept = quaternion_identity;
        serialize_quantized(truncated, kept);
        EXPECT_TRUE(truncated.failed()) << size << " bytes";
        EXPECT_EQ(kept, quaternion_identity) << size << " bytes";
    }
}

} // namespace
