// The orbit camera: it turns around a target point at a distance. The screenshot check builds
// the same camera to project body centres onto the image.
#ifndef EDYN_TESTBED_CAMERA_HPP
#define EDYN_TESTBED_CAMERA_HPP

#include "math3d.hpp"
#include <edyn/math/vector3.hpp>

namespace testbed {

struct orbit_camera {
    edyn::vector3 target{0, 1, 0};
    float yaw{0};      // radians about +y; 0 looks along -z
    float pitch{0.3f}; // radians above the horizon
    float distance{15};
    float fovy{0.8f}; // vertical field of view, radians
    float near_plane{0.1f};
    float far_plane{600};

    edyn::vector3 eye() const;
    mat4 view() const;
    mat4 projection(float aspect) const;

    // Mouse motion in pixels: orbit, pan in the view plane, and zoom by wheel clicks.
    void orbit(float dx, float dy);
    void pan(float dx, float dy, float viewport_height);
    void zoom(float clicks);
};

// Where a world point lands in a width x height image (pixels, origin top left), and whether it
// is in front of the camera.
struct projected_point {
    float x, y;
    bool in_front;
};
projected_point project(const orbit_camera &camera, const edyn::vector3 &p, int width, int height);

// The world-space ray through a pixel (origin top left): from the eye, unit direction.
struct ray {
    edyn::vector3 origin, direction;
};
ray pixel_ray(const orbit_camera &camera, float x, float y, int width, int height);

} // namespace testbed

#endif // EDYN_TESTBED_CAMERA_HPP
