#ifndef EDYN_SERIALIZATION_QUANTIZE_HPP
#define EDYN_SERIALIZATION_QUANTIZE_HPP

// Compact encodings for registry snapshots, which carry every moving body's transform and
// velocities many times per second to every client: bandwidth, not precision, is what runs out.
//
// Vectors: each coordinate is rounded to a multiple of a quantum and written as a zig-zag
// variable-length integer, so that small values take few bytes: a position coordinate under
// 8 m takes 2 bytes, under 1 km 3 bytes, any 5 at most; a velocity under 16 m/s 2 bytes. The
// round-trip error is at most quantum / 2 per coordinate. Positions are meant for a world within
// ±max_quantized_coordinate metres on each axis: values beyond it are clamped to it, and NaN is
// encoded as 0.
//
// Orientations: "smallest three", 6 bytes. The component of largest magnitude is dropped (it is
// recomputed from the unit length) and its sign made positive by negating the whole quaternion,
// which is the same rotation; the other three then lie in [-1/√2, 1/√2] and take 15 bits each.
// Each is off by at most h = √2 / 32767 / 2; the recomputed one follows them (the dropped
// component is at least 1/2), so the decoded rotation differs from the encoded one by at most
// about 4·√3·h ≈ 0.00015 rad (0.009°). Measured over 100,000 random rotations: at most 0.00012
// rad, 0.00005 rad on average (tests/unit/serialization/quantize_test.cpp). Coarser rotations
// cost more than their bytes: with 10 bits a component (4 bytes, up to 0.0042 rad off) a box
// driven alone across a floor, re-simulated by its client from each snapshot, was up to 20.8 cm
// off the server's (edyn-netbench --scenario convergence --bodies 0 --clients 1), as the
// rounded tilt rocks it on its contacts; with 15 bits, 0.48 cm.
//
// Decoding never trusts the bytes: an integer past the bound fails the archive, and any 48 bits
// decode to a unit quaternion.

#include "edyn/config/assert.hpp"
#include "edyn/math/quaternion.hpp"
#include "edyn/math/scalar.hpp"
#include "edyn/math/vector3.hpp"
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace edyn {

/// Quantum of positions in snapshots, in metres: 1/1024 m, about a millimetre.
inline constexpr scalar position_quantum = scalar(1) / 1024;
/// Quantum of linear (m/s) and angular (rad/s) velocities in snapshots: 1/512.
inline constexpr scalar velocity_quantum = scalar(1) / 512;
/// The largest coordinate a quantised vector holds, in metres (2^20, about a thousand
/// kilometres); values beyond it are clamped. Quanta that are powers of two keep the round trip
/// exact in float beyond the point where float itself is coarser than the quantum (8 km for
/// positions).
inline constexpr scalar max_quantized_coordinate = scalar(1 << 20);

namespace detail {

// The largest number of quanta a coordinate may be, so that encoder and decoder agree on the
// bound. Capped where a float still holds integers exactly and int64 holds them comfortably.
inline std::uint64_t max_quantized_steps(scalar quantum) noexcept {
    if (!(quantum > 0)) return 0;
    constexpr auto cap = scalar(std::uint64_t{1} << 52);
    auto steps = std::floor(max_quantized_coordinate / quantum);
    return steps < cap ? std::uint64_t(steps) : std::uint64_t(cap);
}

// Clamps before converting: a float beyond the range of int64 must never reach the conversion.
inline std::int64_t quantize_coordinate(scalar value, scalar quantum, std::uint64_t max_steps) noexcept {
    if (max_steps == 0) return 0;
    auto scaled = value / quantum;
    if (std::isnan(scaled)) return 0;
    auto limit = scalar(max_steps);
    scaled = std::round(std::clamp(scaled, -limit, limit));
    return std::int64_t(scaled);
}

// Zig-zag: 0, -1, 1, -2, 2 ... become 0, 1, 2, 3, 4 ..., so small magnitudes of either sign
// make small LEB128 numbers. Unsigned arithmetic only: no signed overflow for any input.
constexpr std::uint64_t zigzag_encode(std::int64_t value) noexcept {
    return value >= 0 ? std::uint64_t(value) << 1 : (std::uint64_t(-(value + 1)) << 1) | 1;
}

constexpr std::int64_t zigzag_decode(std::uint64_t value) noexcept {
    auto magnitude = std::int64_t(value >> 1);
    return (value & 1) ? -magnitude - 1 : magnitude;
}

inline constexpr scalar smallest_three_bound = scalar(0.70710678118654752440);
inline constexpr std::uint32_t smallest_three_bits = 15;
inline constexpr std::uint32_t smallest_three_max = (std::uint32_t{1} << smallest_three_bits) - 1;
// Where the dropped component's index lies in the packed bits (2 bits; the 48th is unused).
inline constexpr std::uint32_t smallest_three_index_shift = 3 * smallest_three_bits;

// Not constexpr on purpose: reached while checking a quantum_step at compile time, it makes
// the build fail with its name in the message.
inline void quantum_must_be_positive_and_finite() noexcept {}

} // namespace detail

/// The step a vector is rounded to by serialize_quantized: a positive, finite constant of the
/// code, checked when the program is compiled.
///
/// It converts implicitly from a constant expression (position_quantum, velocity_quantum,
/// `scalar(0.01)`), and a zero, negative, infinite or NaN quantum does not compile; neither does
/// a value known only at run time. So a bad quantum can never silently write zeros into a
/// stream, and no archive has to throw.
struct quantum_step {
    /// The quantum (> 0, finite).
    scalar value;
    /// Checks `quantum` at compile time.
    /// @param quantum The step of the rounding; a constant expression, positive and finite.
    consteval quantum_step(scalar quantum)
        : value(quantum) {
        if (!(quantum > 0 && quantum <= std::numeric_limits<scalar>::max())) {
            detail::quantum_must_be_positive_and_finite();
        }
    }
};

/// Writes or reads a vector rounded to a multiple of `step`, compactly.
///
/// Each coordinate is written as a zig-zag variable-length integer number of quanta, so that
/// small values take few bytes: a position coordinate under 8 m takes 2 bytes, under 1 km 3
/// bytes, any 5 at most. The round-trip error is at most quantum / 2 per coordinate. Coordinates
/// beyond ±max_quantized_coordinate are clamped to it and NaN is written as 0. Reading fails the
/// archive on a number past that bound, and leaves `v` as it was then. Both ends must use the
/// same quantum.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param v The vector to write from or read into.
/// @param step The step of the rounding (position_quantum, velocity_quantum): a constant,
/// positive and finite, checked at compile time (quantum_step).
template<typename Archive>
void serialize_quantized(Archive &archive, vector3 &v, quantum_step step) {
    const auto quantum = step.value;
    auto max_steps = detail::max_quantized_steps(quantum);

    if constexpr (Archive::is_output) {
        for (int i = 0; i < 3; ++i) {
            archive.write_varint(
                detail::zigzag_encode(detail::quantize_coordinate(v[i], quantum, max_steps)));
        }
    } else {
        // Read whole or not at all: a failed archive leaves the vector as it was.
        vector3 result;
        for (int i = 0; i < 3; ++i) {
            // Both ends of [-max_steps, max_steps] encode within 2 * max_steps.
            auto encoded = archive.read_varint(2 * max_steps);
            result[i] = scalar(detail::zigzag_decode(encoded)) * quantum;
        }
        if (!archive.failed()) v = result;
    }
}

/// Encodes a rotation in 47 bits ("smallest three").
///
/// The component of largest magnitude is dropped (it is recomputed from the unit length) and its
/// sign made positive by negating the whole quaternion, which is the same rotation; the other
/// three then lie in [-1/√2, 1/√2] and take 15 bits each, the dropped component's index 2 bits.
/// The decoded rotation differs from the encoded one by at most about 0.00015 rad (0.009°).
/// @param q The orientation (x y z w); need not be exactly unit length. A quaternion with a
/// non-finite component, or all zero, is encoded as the identity.
/// @return The packed bits (the low 47 of 64), for unpack_orientation.
inline std::uint64_t pack_orientation(const quaternion &q) noexcept {
    // Dividing by the largest magnitude first normalises quaternions whose squared length
    // would overflow or underflow.
    scalar largest = 0;
    int largest_index = 0;
    for (int i = 0; i < 4; ++i) {
        if (!std::isfinite(q[i])) return pack_orientation(quaternion_identity);
        if (std::abs(q[i]) > largest) {
            largest = std::abs(q[i]);
            largest_index = i;
        }
    }
    if (!(largest > 0)) return pack_orientation(quaternion_identity);

    auto scaled = quaternion{q.x / largest, q.y / largest, q.z / largest, q.w / largest};
    // q and -q are the same rotation: choose the sign that makes the dropped component positive.
    auto factor = (scaled[largest_index] < 0 ? scalar(-1) : scalar(1)) / length(scaled);

    auto bits = std::uint64_t(largest_index) << detail::smallest_three_index_shift;
    auto shift = 2 * detail::smallest_three_bits;
    for (int i = 0; i < 4; ++i) {
        if (i == largest_index) continue;
        auto component = scaled[i] * factor;
        auto t = (component + detail::smallest_three_bound) / (2 * detail::smallest_three_bound);
        auto steps = std::round(std::clamp(t, scalar(0), scalar(1)) * scalar(detail::smallest_three_max));
        bits |= std::uint64_t(steps) << shift;
        shift -= detail::smallest_three_bits;
    }
    return bits;
}

/// Decodes a rotation packed by pack_orientation.
/// @param bits Any bits: bits that pack_orientation never makes still decode to a unit
/// quaternion; those above the 47th are ignored.
/// @return A unit quaternion (x y z w).
inline quaternion unpack_orientation(std::uint64_t bits) noexcept {
    auto largest_index = int((bits >> detail::smallest_three_index_shift) & 3);
    quaternion q{};
    scalar sum_sqr = 0;
    auto shift = 2 * detail::smallest_three_bits;
    for (int i = 0; i < 4; ++i) {
        if (i == largest_index) continue;
        auto steps = (bits >> shift) & detail::smallest_three_max;
        q[i] = scalar(steps) * (2 * detail::smallest_three_bound / scalar(detail::smallest_three_max)) -
               detail::smallest_three_bound;
        sum_sqr += q[i] * q[i];
        shift -= detail::smallest_three_bits;
    }
    // Crafted bits can make the three exceed unit length: the radicand is then clamped and the
    // result normalised, still a rotation.
    q[largest_index] = std::sqrt(std::max(scalar(1) - sum_sqr, scalar(0)));
    auto len = length(q);
    // Unreachable with an odd number of steps (none decodes to 0), kept so that a change of
    // width stays safe.
    if (!(len > epsilon)) return quaternion_identity;
    return {q.x / len, q.y / len, q.z / len, q.w / len};
}

/// Writes or reads an orientation in 6 bytes, with pack_orientation and unpack_orientation.
/// A value read is always a unit quaternion; on failure `q` is left as it was.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param q The orientation to write from or read into.
template<typename Archive>
void serialize_quantized(Archive &archive, quaternion &q) {
    // Three 16-bit parts, the lowest first.
    if constexpr (Archive::is_output) {
        auto bits = pack_orientation(q);
        for (int i = 0; i < 3; ++i)
            archive(std::uint16_t(bits >> (16 * i)));
    } else {
        std::uint64_t bits = 0;
        for (int i = 0; i < 3; ++i) {
            std::uint16_t part{};
            archive(part);
            bits |= std::uint64_t(part) << (16 * i);
        }
        if (!archive.failed()) q = unpack_orientation(bits);
    }
}

} // namespace edyn

#endif // EDYN_SERIALIZATION_QUANTIZE_HPP
