// Ray casts into a world of a box, a sphere and the ground: the first body hit, where (lerp of
// the ray's ends by the fraction), the surface normal, and what the shape adds (a box's face).
#include <cmath>
#include <cstdio>
#include <edyn/edyn.hpp>
#include <vector>

namespace {

bool near(const edyn::vector3 &a, const edyn::vector3 &b) { return edyn::distance(a, b) < 1e-4f; }

void keep(edyn::raycast_result &out, edyn::raycast_id_type, const edyn::raycast_result &result, edyn::vector3,
          edyn::vector3) {
    out = result;
}

// In the asynchronous mode (the default) the bodies live in the simulation worker, so the ray
// is cast there: raycast_async hands the result to a delegate during a later update(). A game
// would carry on and act on it then; this example waits for it. (edyn::raycast casts at once,
// in the sequential modes and inside step callbacks.)
edyn::raycast_result cast(edyn::registry &registry, const edyn::vector3 &p0, const edyn::vector3 &p1,
                          const std::vector<edyn::entity> &ignore = {}) {
    edyn::raycast_result result;
    edyn::raycast_delegate_type delegate;
    delegate.connect<&keep>(result);
    edyn::raycast_async(registry, p0, p1, delegate, ignore);
    edyn::wait_for_simulation(registry);
    return result;
}

} // namespace

int main() {
    edyn::registry registry;
    edyn::attach(registry);

    auto ground_def = edyn::rigidbody_def();
    ground_def.kind = edyn::rigidbody_kind::rb_static;
    ground_def.shape = edyn::plane_shape{{0, 1, 0}, 0};
    auto ground = edyn::make_rigidbody(registry, ground_def);

    auto def = edyn::rigidbody_def();
    def.kind = edyn::rigidbody_kind::rb_static;
    def.shape = edyn::box_shape{0.5, 0.5, 0.5};
    def.position = {0, 0.5, 0};
    auto box = edyn::make_rigidbody(registry, def);
    def.shape = edyn::sphere_shape{0.5};
    def.position = {3, 0.5, 0};
    auto sphere = edyn::make_rigidbody(registry, def);

    bool ok = true;

    // Straight down onto the box: its upper face (face 2, +y) at y = 1.
    edyn::vector3 p0{0.2, 5, 0.1}, p1{0.2, -5, 0.1};
    auto result = cast(registry, p0, p1);
    if (result.entity != box) {
        std::printf("the ray down onto the box missed it\n");
        return 1;
    }
    auto intersection = edyn::lerp(p0, p1, result.fraction);
    auto info = std::get<edyn::box_raycast_info>(result.info_var);
    std::printf("down onto the box: hit at (%.2f, %.3f, %.2f), face %zu, normal (%.0f, %.0f, %.0f) "
                "(expected y = 1, face 2, normal up)\n",
                intersection.x, intersection.y, intersection.z, info.face_index, result.normal.x,
                result.normal.y, result.normal.z);
    ok = near(intersection, {0.2, 1, 0.1}) && info.face_index == 2 && near(result.normal, {0, 1, 0});

    // Sideways through the box towards the sphere: the box is first; ignoring it, the sphere.
    p0 = {-5, 0.5, 0};
    p1 = {5, 0.5, 0};
    result = cast(registry, p0, p1, {box});
    intersection = edyn::lerp(p0, p1, result.fraction);
    std::printf("sideways, box ignored: hit the %s at x = %.3f (expected the sphere at x = 2.5)\n",
                result.entity == sphere ? "sphere" : "wrong body", intersection.x);
    ok = ok && result.entity == sphere && near(intersection, {2.5, 0.5, 0});

    // Slanted at the sphere from above: the hit lies on its surface, the normal along the radius.
    p0 = {3, 3, 2};
    p1 = {3, 0.5, 0};
    result = cast(registry, p0, p1);
    intersection = edyn::lerp(p0, p1, result.fraction);
    auto from_centre = edyn::distance(intersection, edyn::vector3{3, 0.5, 0});
    auto radial = edyn::dot(result.normal, edyn::normalize(intersection - edyn::vector3{3, 0.5, 0}));
    std::printf(
        "slanted at the sphere: hit %.4f m from its centre (expected the radius, 0.5), normal along the "
        "radius: cos = %.4f (expected 1)\n",
        from_centre, radial);
    ok = ok && result.entity == sphere && std::abs(from_centre - 0.5f) < 1e-4f && radial > 0.9999f;

    // Past everything onto the ground, then a ray that hits nothing.
    p0 = {-3, 2, 0};
    p1 = {-3, -2, 0};
    result = cast(registry, p0, p1);
    auto miss = cast(registry, {0, 5, 0}, {0, 10, 0});
    std::printf("onto the ground: fraction %.2f (expected 0.50); upwards: %s (expected nothing)\n",
                result.fraction, miss.entity == edyn::null ? "nothing" : "a hit");
    ok = ok && result.entity == ground && std::abs(result.fraction - 0.5f) < 1e-4f &&
         miss.entity == edyn::null;

    edyn::detach(registry);
    return ok ? 0 : 1;
}
