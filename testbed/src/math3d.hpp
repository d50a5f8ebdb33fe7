// Small single-precision matrix helpers for drawing: column-major 4x4 matrices as OpenGL takes
// them, built from edyn's vectors.
#ifndef EDYN_TESTBED_MATH3D_HPP
#define EDYN_TESTBED_MATH3D_HPP

#include <array>
#include <cmath>
#include <edyn/math/vector3.hpp>

namespace testbed {

struct vec4 {
    float x, y, z, w;
};

// m[column * 4 + row].
struct mat4 {
    std::array<float, 16> m{};
    float &at(int row, int col) { return m[std::size_t(col * 4 + row)]; }
    float at(int row, int col) const { return m[std::size_t(col * 4 + row)]; }
};

inline mat4 operator*(const mat4 &a, const mat4 &b) {
    mat4 r;
    for (int c = 0; c < 4; ++c)
        for (int row = 0; row < 4; ++row) {
            float s = 0;
            for (int k = 0; k < 4; ++k)
                s += a.at(row, k) * b.at(k, c);
            r.at(row, c) = s;
        }
    return r;
}

inline vec4 operator*(const mat4 &a, const vec4 &v) {
    float in[4]{v.x, v.y, v.z, v.w}, out[4]{};
    for (int row = 0; row < 4; ++row)
        for (int k = 0; k < 4; ++k)
            out[row] += a.at(row, k) * in[k];
    return {out[0], out[1], out[2], out[3]};
}

inline mat4 look_at(const edyn::vector3 &eye, const edyn::vector3 &target, const edyn::vector3 &up) {
    auto f = edyn::normalize(target - eye);
    auto s = edyn::normalize(edyn::cross(f, up));
    auto u = edyn::cross(s, f);
    mat4 r;
    r.at(0, 0) = float(s.x), r.at(0, 1) = float(s.y), r.at(0, 2) = float(s.z);
    r.at(1, 0) = float(u.x), r.at(1, 1) = float(u.y), r.at(1, 2) = float(u.z);
    r.at(2, 0) = float(-f.x), r.at(2, 1) = float(-f.y), r.at(2, 2) = float(-f.z);
    r.at(0, 3) = float(-edyn::dot(s, eye));
    r.at(1, 3) = float(-edyn::dot(u, eye));
    r.at(2, 3) = float(edyn::dot(f, eye));
    r.at(3, 3) = 1;
    return r;
}

inline mat4 perspective(float fovy, float aspect, float near, float far) {
    float t = 1.0f / std::tan(fovy / 2);
    mat4 r;
    r.at(0, 0) = t / aspect;
    r.at(1, 1) = t;
    r.at(2, 2) = (far + near) / (near - far);
    r.at(2, 3) = 2 * far * near / (near - far);
    r.at(3, 2) = -1;
    return r;
}

} // namespace testbed

#endif // EDYN_TESTBED_MATH3D_HPP
