// Shifting the centre of mass. A box rests on the edge of a table with most of it on the table:
// it stands. Moving its centre of mass past the edge, with the box where it is, tips it off:
// a body on a support stands exactly when its centre of mass is above the support.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <edyn/edyn.hpp>

namespace {

// Angle between the box's up axis and the world's, in degrees.
edyn::scalar tilt(const edyn::registry &registry, edyn::entity entity) {
    auto up = edyn::rotate(registry.get<edyn::orientation>(entity), edyn::vector3{0, 1, 0});
    return edyn::to_degrees(std::acos(std::clamp(up.y, edyn::scalar(-1), edyn::scalar(1))));
}

} // namespace

int main() {
    edyn::registry registry;
    edyn::attach(registry);

    // A table whose top ends at x = 0 and lies at y = 1.
    auto table_def = edyn::rigidbody_def();
    table_def.kind = edyn::rigidbody_kind::rb_static;
    table_def.shape = edyn::box_shape{1, 0.5, 1};
    table_def.position = {-1, 0.5, 0};
    edyn::make_rigidbody(registry, table_def);

    // A 1 m box from x = -0.8 to 0.2: 0.2 m hang over the edge, its centre 0.3 m inside.
    auto def = edyn::rigidbody_def();
    def.mass = 10;
    def.shape = edyn::box_shape{0.5, 0.5, 0.5};
    def.position = {-0.3, 1.5, 0};
    auto box = edyn::make_rigidbody(registry, def);

    for (int step = 0; step < 60; ++step)
        edyn::step_simulation(registry);
    edyn::wait_for_simulation(registry);
    auto standing_tilt = tilt(registry, box);
    std::printf("centre of mass at x = %.2f m, 0.30 m inside the edge: box tilted %.2f degrees after 1 s\n",
                registry.get<edyn::position>(box).x, standing_tilt);

    // 0.45 m towards the overhang, in object space from the origin: the centre of mass moves to
    // x = 0.15, past the edge. position (the centre of mass) moves with it; the origin does not.
    edyn::set_center_of_mass(registry, box, {0.45, 0, 0});
    auto com = registry.get<edyn::position>(box);
    auto origin = edyn::get_rigidbody_origin(registry, box);
    std::printf("centre of mass moved to x = %.2f m, 0.15 m past the edge; the origin stayed at x = %.2f m\n",
                com.x, origin.x);

    for (int step = 0; step < 60; ++step)
        edyn::step_simulation(registry);
    edyn::wait_for_simulation(registry);
    auto tipped_tilt = tilt(registry, box);
    auto y = registry.get<edyn::position>(box).y;
    std::printf("box tilted %.1f degrees and its centre of mass dropped to y = %.2f m one second later "
                "(expected: it tips off the table)\n",
                tipped_tilt, y);

    edyn::detach(registry);
    auto ok = standing_tilt < 0.5f && std::abs(com.x - 0.15f) < 0.01f && std::abs(origin.x + 0.3f) < 0.01f &&
              tipped_tilt > 30 && y < 1.2f;
    return ok ? 0 : 1;
}
