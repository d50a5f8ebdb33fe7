#ifndef EDYN_SERIALIZATION_MATH_TYPES_HPP
#define EDYN_SERIALIZATION_MATH_TYPES_HPP

// Serialization of edyn's math types and entities, at full precision. Snapshots quantise
// transforms and velocities instead (serialization/quantize.hpp).

#include "edyn/ecs/entity.hpp"
#include "edyn/math/matrix3x3.hpp"
#include "edyn/math/quaternion.hpp"
#include "edyn/math/vector3.hpp"
#include "edyn/serialization/memory_archive.hpp"

namespace edyn {

/// Writes or reads a vector at full precision: x, y, z.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param v The vector to write from or read into.
template<typename Archive>
void serialize(Archive &archive, vector3 &v) {
    archive(v.x, v.y, v.z);
}

/// Writes or reads a quaternion at full precision: x, y, z, w. Not normalised nor checked.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param q The quaternion to write from or read into.
template<typename Archive>
void serialize(Archive &archive, quaternion &q) {
    archive(q.x, q.y, q.z, q.w);
}

/// Writes or reads a 3x3 matrix at full precision, row by row.
/// @param archive A memory_output_archive or memory_input_archive.
/// @param m The matrix to write from or read into.
template<typename Archive>
void serialize(Archive &archive, matrix3x3 &m) {
    archive(m.row[0], m.row[1], m.row[2]);
}

} // namespace edyn

#endif // EDYN_SERIALIZATION_MATH_TYPES_HPP
