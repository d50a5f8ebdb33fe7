// Three ways to keep bodies from colliding: groups and masks, exclusion pairs, and a filter
// function of the program's own. Each filtered body falls through what it would have landed on.
#include <cmath>
#include <cstdio>
#include <edyn/edyn.hpp>

namespace {

// The program's own rule, on top of the default one: ghosts pass through everything.
struct ghost {};

bool should_collide(const edyn::registry &registry, edyn::entity first, edyn::entity second) {
    if (registry.any_of<ghost>(first) || registry.any_of<ghost>(second)) return false;
    return edyn::should_collide_default(registry, first, second);
}

edyn::rigidbody_def ball_at(const edyn::vector3 &position) {
    auto def = edyn::rigidbody_def();
    def.shape = edyn::sphere_shape{0.5};
    def.position = position;
    return def;
}

bool check(const char *what, edyn::scalar y, edyn::scalar expected, edyn::scalar tolerance) {
    auto ok = std::abs(y - expected) < tolerance;
    std::printf("%-48s y = %7.3f m (expected %.3f)%s\n", what, y, expected, ok ? "" : "  <-- wrong");
    return ok;
}

} // namespace

int main() {
    edyn::registry registry;
    edyn::attach(registry);
    // The filter runs where the simulation runs, in the worker: it reads the worker's registry,
    // so the ghost tag must travel there.
    edyn::register_external_components<ghost>(registry);
    edyn::set_should_collide(registry, &should_collide);

    auto ground_def = edyn::rigidbody_def();
    ground_def.kind = edyn::rigidbody_kind::rb_static;
    ground_def.shape = edyn::plane_shape{{0, 1, 0}, 0};
    auto ground = edyn::make_rigidbody(registry, ground_def);

    // Groups and masks: the lower ball is in group 1 and ignores group 2; the upper one is in
    // group 2 and ignores group 1. The upper one falls through the lower one onto the ground.
    auto lower_def = ball_at({0, 0.5, 0});
    lower_def.collision_group = 1ull;
    lower_def.collision_mask = ~(1ull << 1);
    auto lower = edyn::make_rigidbody(registry, lower_def);
    auto upper_def = ball_at({0.2, 3, 0});
    upper_def.collision_group = 1ull << 1;
    upper_def.collision_mask = ~1ull;
    auto upper = edyn::make_rigidbody(registry, upper_def);

    // The same again with no filter: it lands on top.
    edyn::make_rigidbody(registry, ball_at({3, 0.5, 0}));
    auto stacked = edyn::make_rigidbody(registry, ball_at({3, 3, 0}));

    // An exclusion pair: this ball and the ground never collide.
    auto excluded = edyn::make_rigidbody(registry, ball_at({6, 3, 0}));
    edyn::exclude_collision(registry, excluded, ground);

    // The program's filter.
    auto spook = edyn::make_rigidbody(registry, ball_at({9, 3, 0}));
    registry.emplace<ghost>(spook);

    for (int step = 0; step < 60; ++step)
        edyn::step_simulation(registry);
    edyn::wait_for_simulation(registry);

    auto y = [&](edyn::entity e) { return registry.get<edyn::position>(e).y; };
    // In 1 s of free fall from 3 m a ball drops 4.9 m, to -1.9 m.
    bool ok = check("group 2 ball fell through the group 1 ball:", y(upper), 0.5, 0.01);
    ok = check("group 1 ball stayed on the ground:", y(lower), 0.5, 0.01) && ok;
    ok = check("unfiltered ball landed on the other:", y(stacked), 1.5, 0.01) && ok;
    ok = check("ball excluded from the ground fell through it:", y(excluded), 3 - 4.9f, 0.05) && ok;
    ok = check("ghost fell through the ground:", y(spook), 3 - 4.9f, 0.05) && ok;

    // Filters can change at any time. Both must let the other's group in: opening both masks,
    // the ball inside the other (0.2 m off centre) is pushed out.
    for (auto ball : {lower, upper})
        registry.patch<edyn::collision_filter>(ball, [](auto &filter) { filter.mask = ~0ull; });
    for (int step = 0; step < 60; ++step)
        edyn::step_simulation(registry);
    edyn::wait_for_simulation(registry);
    auto apart = edyn::distance(registry.get<edyn::position>(upper), registry.get<edyn::position>(lower));
    auto separated = apart > 0.99f;
    std::printf("after the masks changed, the balls were pushed %.3f m apart (expected at least 1)%s\n",
                apart, separated ? "" : "  <-- wrong");
    ok = ok && separated;

    edyn::detach(registry);
    return ok ? 0 : 1;
}
