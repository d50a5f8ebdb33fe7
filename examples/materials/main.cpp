// Material mixing: when two bodies touch, their materials are combined (restitution: the
// larger one) unless a pair of material ids has its own entry. Balls dropped from 2 m bounce to
// e^2 of that height, e being the mixed restitution.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <edyn/edyn.hpp>

namespace {

constexpr edyn::material_id_type ball_mat_id = 0;
constexpr edyn::material_id_type table_mat_id = 1;

edyn::entity drop_ball(edyn::registry &registry, edyn::scalar x, const edyn::material &material) {
    auto def = edyn::rigidbody_def();
    def.shape = edyn::sphere_shape{0.1};
    def.position = {x, 2.1, 0};
    def.material = material;
    return edyn::make_rigidbody(registry, def);
}

} // namespace

int main() {
    edyn::registry registry;
    edyn::attach(registry);

    // Ball and table have their own entry, as in the manual; ball on ball would use the other.
    auto ball_ball_mat = edyn::material_base{};
    ball_ball_mat.friction = 0.05;
    ball_ball_mat.restitution = 0.95;
    edyn::insert_material_mixing(registry, ball_mat_id, ball_mat_id, ball_ball_mat);
    auto table_ball_mat = edyn::material_base{};
    table_ball_mat.friction = 0.2;
    table_ball_mat.restitution = 0.5;
    edyn::insert_material_mixing(registry, ball_mat_id, table_mat_id, table_ball_mat);

    auto table_def = edyn::rigidbody_def();
    table_def.kind = edyn::rigidbody_kind::rb_static;
    table_def.shape = edyn::plane_shape{{0, 1, 0}, 0};
    table_def.material->id = table_mat_id;
    // Used with materials that have no entry for the table.
    table_def.material->restitution = 0.2;
    table_def.material->friction = 0.2;
    auto table = edyn::make_rigidbody(registry, table_def);

    // A billiard ball: its own restitution of 0.9 is overridden by the pair's 0.5.
    auto billiard = edyn::material{};
    billiard.id = ball_mat_id;
    billiard.restitution = 0.9;
    // A rubber ball without an id: mixed by default, max(0.8, 0.2) = 0.8.
    auto rubber = edyn::material{};
    rubber.restitution = 0.8;
    // A clay ball without an id: max(0, 0.2) = 0.2, the table's.
    auto clay = edyn::material{};
    clay.restitution = 0;

    struct drop {
        const char *name;
        edyn::entity entity;
        edyn::scalar restitution;
        edyn::scalar peak{0};
        bool bounced{false};
    } drops[] = {{"billiard ball (pair entry)", drop_ball(registry, 0, billiard), edyn::scalar(0.5)},
                 {"rubber ball (default mixing)", drop_ball(registry, 1, rubber), edyn::scalar(0.8)},
                 {"clay ball (default mixing)", drop_ball(registry, 2, clay), edyn::scalar(0.2)}};

    // The mixed material the contacts will use.
    for (auto &d : drops) {
        auto mixed = edyn::get_mixed_material(registry, registry.get<edyn::material>(d.entity),
                                              registry.get<edyn::material>(table));
        if (mixed.restitution != d.restitution) {
            std::printf("%s: mixed restitution %.2f, expected %.2f\n", d.name, mixed.restitution,
                        d.restitution);
            return 1;
        }
    }

    // The highest point after the first bounce (later bounces are lower).
    for (int step = 0; step < 120; ++step) {
        edyn::step_simulation(registry);
        edyn::wait_for_simulation(registry);
        for (auto &d : drops) {
            auto vy = registry.get<edyn::linvel>(d.entity).y;
            if (vy > 0) d.bounced = true;
            if (d.bounced && vy > -1)
                d.peak = std::max(d.peak, registry.get<edyn::position>(d.entity).y - 0.1f);
        }
    }

    bool ok = true;
    // A bounce may begin up to one sub-step of travel (6.3 m/s / 360 Hz, 1.7 cm) above the table.
    const edyn::scalar tolerance = 0.02f;
    for (auto &d : drops) {
        auto expected = 2 * d.restitution * d.restitution;
        auto good = d.bounced && std::abs(d.peak - expected) < tolerance;
        ok = ok && good;
        std::printf("%-29s e = %.2f bounced to %.3f m (expected e^2 x 2 m = %.3f)%s\n", d.name, d.restitution,
                    d.peak, expected, good ? "" : "  <-- wrong");
    }
    edyn::detach(registry);
    return ok ? 0 : 1;
}
