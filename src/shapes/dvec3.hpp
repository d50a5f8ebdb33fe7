#ifndef EDYN_SRC_SHAPES_DVEC3_HPP
#define EDYN_SRC_SHAPES_DVEC3_HPP

#include "edyn/math/vector3.hpp"
#include <algorithm>
#include <cmath>
#include <limits>

// Double-precision vector for the construction-time geometry of convex meshes (hull, normals,
// validation), whose decisions must stay consistent even in float builds. Private to src/.
namespace edyn::detail {

// Relative rounding of the input coordinates that construction tolerances are multiples of:
// the scalar epsilon, with a floor in double builds so that the double computations' own
// rounding stays far below it.
inline constexpr double coordinate_rounding =
    std::max(double(std::numeric_limits<scalar>::epsilon()), 250 * std::numeric_limits<double>::epsilon());

struct dvec3 {
    double x, y, z;
};

inline dvec3 to_dvec3(const vector3 &v) { return {double(v.x), double(v.y), double(v.z)}; }
inline vector3 to_vector3(const dvec3 &v) { return {scalar(v.x), scalar(v.y), scalar(v.z)}; }

inline dvec3 operator+(const dvec3 &a, const dvec3 &b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline dvec3 operator-(const dvec3 &a, const dvec3 &b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline dvec3 operator*(const dvec3 &v, double s) { return {v.x * s, v.y * s, v.z * s}; }
inline dvec3 &operator+=(dvec3 &a, const dvec3 &b) { return a = a + b; }
inline double dot(const dvec3 &a, const dvec3 &b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline dvec3 cross(const dvec3 &a, const dvec3 &b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(const dvec3 &v) { return std::sqrt(dot(v, v)); }
inline double component(const dvec3 &v, int i) { return i == 0 ? v.x : (i == 1 ? v.y : v.z); }

} // namespace edyn::detail

#endif // EDYN_SRC_SHAPES_DVEC3_HPP
