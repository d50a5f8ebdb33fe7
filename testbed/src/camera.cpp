#include "camera.hpp"
#include <algorithm>
#include <cmath>

namespace testbed {

namespace {

edyn::vector3 forward(const orbit_camera &c) {
    return {-std::sin(c.yaw) * std::cos(c.pitch), -std::sin(c.pitch), -std::cos(c.yaw) * std::cos(c.pitch)};
}

} // namespace

edyn::vector3 orbit_camera::eye() const { return target - forward(*this) * edyn::scalar(distance); }

mat4 orbit_camera::view() const { return look_at(eye(), target, {0, 1, 0}); }

mat4 orbit_camera::projection(float aspect) const { return perspective(fovy, aspect, near_plane, far_plane); }

void orbit_camera::orbit(float dx, float dy) {
    yaw -= dx * 0.005f;
    pitch = std::clamp(pitch + dy * 0.005f, -1.5f, 1.5f);
}

void orbit_camera::pan(float dx, float dy, float viewport_height) {
    auto f = forward(*this);
    auto right = edyn::normalize(edyn::cross(f, {0, 1, 0}));
    auto up = edyn::cross(right, f);
    // One pixel moves the target by the size of a pixel at the target's distance.
    auto scale = edyn::scalar(2 * distance * std::tan(fovy / 2) / viewport_height);
    target += (right * edyn::scalar(-dx) + up * edyn::scalar(dy)) * scale;
}

void orbit_camera::zoom(float clicks) {
    distance = std::clamp(distance * std::pow(0.9f, clicks), 1.0f, 400.0f);
}

projected_point project(const orbit_camera &camera, const edyn::vector3 &p, int width, int height) {
    auto clip = camera.projection(float(width) / float(height)) * camera.view() *
                vec4{float(p.x), float(p.y), float(p.z), 1};
    if (clip.w <= 0) return {0, 0, false};
    float nx = clip.x / clip.w, ny = clip.y / clip.w;
    return {(nx + 1) / 2 * float(width), (1 - ny) / 2 * float(height), true};
}

ray pixel_ray(const orbit_camera &camera, float x, float y, int width, int height) {
    auto f = forward(camera);
    auto right = edyn::normalize(edyn::cross(f, {0, 1, 0}));
    auto up = edyn::cross(right, f);
    float t = std::tan(camera.fovy / 2);
    float aspect = float(width) / float(height);
    float nx = (2 * x / float(width) - 1) * t * aspect;
    float ny = (1 - 2 * y / float(height)) * t;
    auto dir = edyn::normalize(f + right * edyn::scalar(nx) + up * edyn::scalar(ny));
    return {camera.eye(), dir};
}

} // namespace testbed
