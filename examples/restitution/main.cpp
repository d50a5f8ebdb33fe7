// Newton's cradle: five touching steel balls on strings, the first one pulled back and let go.
// With restitution 1 the shock runs through the row and the last ball leaves with the first
// one's speed while the others stay put, which takes the restitution solver: it solves the
// touching pairs' contacts in turn until every one of them separates.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <edyn/edyn.hpp>
#include <vector>

int main() {
    edyn::registry registry;
    edyn::attach(registry);

    const edyn::scalar radius = 0.05f, string = 0.5f, bar_height = 1;
    const auto pulled = edyn::to_radians(30);
    std::vector<edyn::entity> balls;
    for (int i = 0; i < 5; ++i) {
        // Each ball hangs from its own point on the bar, 2 r apart, so that neighbours touch.
        auto x = (i - 2) * 2 * radius;
        auto hook_def = edyn::rigidbody_def();
        hook_def.kind = edyn::rigidbody_kind::rb_static;
        hook_def.position = {x, bar_height, 0};
        auto hook = edyn::make_rigidbody(registry, hook_def);

        auto def = edyn::rigidbody_def();
        def.mass = 0.5f;
        def.shape = edyn::sphere_shape{radius};
        def.material->restitution = 1;
        def.material->friction = 0;
        def.position = {x, bar_height - string, 0};
        if (i == 0) {
            def.position =
                edyn::vector3{x - string * std::sin(pulled), bar_height - string * std::cos(pulled), 0};
        }
        auto ball = edyn::make_rigidbody(registry, def);
        edyn::make_constraint<edyn::distance_constraint>(
            registry, hook, ball, [&](edyn::distance_constraint &c) { c.distance = string; });
        balls.push_back(ball);
    }

    // Until the first ball reaches the others, then for a tenth of a second after.
    edyn::scalar first_speed = 0, last_speed = 0, others_speed = 0;
    int impact_step = -1;
    for (int step = 0; step < 120 && (impact_step < 0 || step < impact_step + 6); ++step) {
        auto speed_before = edyn::length(registry.get<edyn::linvel>(balls[0]));
        edyn::step_simulation(registry);
        edyn::wait_for_simulation(registry);
        auto speed_last = edyn::length(registry.get<edyn::linvel>(balls[4]));
        if (impact_step < 0 && speed_last > 0.01f) {
            impact_step = step;
            first_speed = speed_before;
        }
        // Fastest as it leaves: from then on it climbs and slows.
        last_speed = std::max(last_speed, speed_last);
    }
    for (int i = 0; i < 4; ++i)
        others_speed = std::max(others_speed, edyn::length(registry.get<edyn::linvel>(balls[i])));

    // Energy: the first ball arrives at sqrt(2 g L (1 - cos 30)).
    auto expected = std::sqrt(2 * 9.8f * string * (1 - std::cos(pulled)));
    std::printf("first ball hit at %.3f m/s (expected sqrt(2 g L (1 - cos 30)) = %.3f); "
                "the last one left at %.3f m/s, the others move at %.3f m/s at most\n",
                first_speed, expected, last_speed, others_speed);
    edyn::detach(registry);
    auto ok = impact_step >= 0 && std::abs(first_speed - expected) < 0.02f * expected &&
              std::abs(last_speed - first_speed) < 0.05f * first_speed && others_speed < 0.1f * first_speed;
    return ok ? 0 : 1;
}
