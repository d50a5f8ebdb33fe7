#ifndef EDYN_SRC_SHAPES_INVALID_ARGUMENT_HPP
#define EDYN_SRC_SHAPES_INVALID_ARGUMENT_HPP

#include "edyn/math/matrix3x3.hpp"
#include "edyn/math/quaternion.hpp"
#include <sstream>
#include <stdexcept>
#include <string>

// Message building for the std::invalid_argument thrown by shape validation. Private to src/.
namespace edyn::detail {

inline std::ostream &operator<<(std::ostream &os, const vector3 &v) {
    return os << '(' << v.x << ", " << v.y << ", " << v.z << ')';
}

inline std::ostream &operator<<(std::ostream &os, const matrix3x3 &m) {
    return os << '(' << m[0] << ", " << m[1] << ", " << m[2] << ')';
}

inline std::ostream &operator<<(std::ostream &os, const quaternion &q) {
    return os << '(' << q.x << ", " << q.y << ", " << q.z << ", " << q.w << ')';
}

// Concatenates the arguments with operator<< (default stream precision, so 0.5 prints as 0.5
// and NaN as nan).
template<typename... Args>
std::string concat(const Args &...args) {
    std::ostringstream os;
    (os << ... << args);
    return os.str();
}

template<typename... Args>
[[noreturn]] void throw_invalid_argument(const Args &...args) {
    throw std::invalid_argument(concat(args...));
}

inline bool positive_finite(scalar value) noexcept { return std::isfinite(value) && value > 0; }

} // namespace edyn::detail

#endif // EDYN_SRC_SHAPES_INVALID_ARGUMENT_HPP
