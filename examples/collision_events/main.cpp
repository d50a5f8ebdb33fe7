// A billiards break heard through collision events: every contact between balls that starts
// is printed with its impulse, which is what a game would play a click at (louder for a
// larger impulse). The events come at the end of the step, so the impulses are already there:
// the cue ball's first click must carry the momentum the cue ball lost in that step.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <edyn/edyn.hpp>

namespace {

constexpr edyn::scalar radius = 0.028575f; // 57.15 mm balls
constexpr edyn::scalar ball_mass = 0.17f;

// 0 is the cue ball, 1 to 15 the rack.
struct ball_number {
    int value;
};

struct break_log {
    int clicks{0};
    int silent{0};
    edyn::scalar first_cue_impulse{0};
};

// As in the manual: the manifold's points carry the solver's and the restitution solver's
// impulses apart; their sum is the whole impulse.
void contact_started(edyn::registry &registry, edyn::entity entity) {
    auto &manifold = registry.get<edyn::contact_manifold>(entity);
    auto *a = registry.try_get<ball_number>(manifold.body[0]);
    auto *b = registry.try_get<ball_number>(manifold.body[1]);
    if (!a || !b) return; // the table is felt: silent
    edyn::scalar normal_impulse = 0;
    for (unsigned i = 0; i < manifold.num_points; ++i) {
        auto &cp = manifold.point[manifold.ids[i]];
        normal_impulse += cp.normal_impulse + cp.normal_restitution_impulse;
    }
    auto &log = registry.ctx().get<break_log>();
    // Contacts begin a little before the surfaces touch, so balls that pass close by start one
    // without an impulse: no sound.
    if (normal_impulse < 1e-4f) {
        ++log.silent;
        return;
    }
    if (log.clicks == 0 && (a->value == 0 || b->value == 0)) log.first_cue_impulse = normal_impulse;
    ++log.clicks;
    std::printf("t = %.3f s  click: ball %2d and ball %2d, impulse %.4f N s\n",
                edyn::get_simulation_time(registry), std::min(a->value, b->value),
                std::max(a->value, b->value), normal_impulse);
}

edyn::entity make_ball(edyn::registry &registry, int number, const edyn::vector3 &position,
                       const edyn::vector3 &velocity = edyn::vector3_zero) {
    auto def = edyn::rigidbody_def();
    def.mass = ball_mass;
    def.shape = edyn::sphere_shape{radius};
    def.material->restitution = 0.95f;
    def.material->friction = 0.2f;
    def.position = position;
    def.linvel = velocity;
    auto entity = edyn::make_rigidbody(registry, def);
    registry.emplace<ball_number>(entity, number);
    return entity;
}

} // namespace

int main() {
    edyn::registry registry;
    edyn::attach(registry);
    registry.ctx().emplace<break_log>();
    edyn::on_contact_started(registry).connect<&contact_started>(registry);

    auto table_def = edyn::rigidbody_def();
    table_def.kind = edyn::rigidbody_kind::rb_static;
    table_def.shape = edyn::plane_shape{{0, 1, 0}, 0};
    table_def.material->restitution = 0.5f;
    table_def.material->friction = 0.2f;
    edyn::make_rigidbody(registry, table_def);

    // The rack: five rows, the apex towards the cue ball. Balls set touching would be in contact
    // from the first step, and a contact starts only once: 3 cm gaps make each hit a start.
    const edyn::scalar spacing = 2 * radius + 0.03f;
    int number = 1;
    for (int row = 0; row < 5; ++row) {
        for (int i = 0; i <= row; ++i) {
            auto x = row * spacing * std::sqrt(3.0f) / 2;
            auto z = (i - row / 2.0f) * spacing;
            make_ball(registry, number++, {x, radius, z});
        }
    }
    const edyn::scalar cue_speed = 4;
    auto cue = make_ball(registry, 0, {-0.5f, radius, 0}, {cue_speed, 0, 0});

    edyn::scalar cue_momentum_before = 0, cue_momentum_lost = 0;
    for (int step = 0; step < 60; ++step) {
        auto before = ball_mass * registry.get<edyn::linvel>(cue).x;
        auto clicks = registry.ctx().get<break_log>().clicks;
        edyn::step_simulation(registry);
        edyn::wait_for_simulation(registry);
        if (clicks == 0 && registry.ctx().get<break_log>().clicks > 0) {
            cue_momentum_before = before;
            cue_momentum_lost = before - ball_mass * registry.get<edyn::linvel>(cue).x;
        }
    }

    auto &log = registry.ctx().get<break_log>();
    // A head-on hit between equal balls transfers m v (1 + e) / 2.
    auto expected = cue_momentum_before * (1 + 0.95f) / 2;
    std::printf("%d clicks, %d silent contacts; the first click carried %.4f N s, the cue ball lost %.4f N s "
                "in that step (expected m v (1 + e) / 2 = %.4f)\n",
                log.clicks, log.silent, log.first_cue_impulse, cue_momentum_lost, expected);
    // The table's friction takes a little of the momentum too: mu m g dt, about 1% of it.
    auto ok = log.clicks >= 5 &&
              std::abs(log.first_cue_impulse - cue_momentum_lost) < 0.03f * cue_momentum_lost &&
              std::abs(log.first_cue_impulse - expected) < 0.03f * expected;
    edyn::detach(registry);
    return ok ? 0 : 1;
}
