// The asynchronous mode against the sequential one: the same random program (bodies made and
// destroyed, shapes, kinds, materials, gravity, centres of mass, impulses, joints, exclusions),
// run a step at a time in both, must give the same motion bit for bit at every step. Replication
// faults (an operation lost, sent to the wrong entity, or applied out of order) show here.
#include <cstring>
#include <edyn/edyn.hpp>
#include <gtest/gtest.h>
#include <random>
#include <vector>

namespace differential {

using namespace edyn;

struct world {
    registry reg;
    std::vector<entity> bodies; // in the order they were made; null once destroyed
    explicit world(execution_mode mode) {
        attach(reg, init_config{mode});
        rigidbody_def ground;
        ground.kind = rigidbody_kind::rb_static;
        ground.shape = box_shape{20, 0.5, 20};
        ground.position = {0, -0.5, 0};
        bodies.push_back(make_rigidbody(reg, ground));
    }
    ~world() { detach(reg); }

    // The body made `pick`-th (modulo the count), if it is alive and not the ground.
    entity body(unsigned pick) const {
        auto i = pick % bodies.size();
        auto e = bodies[i];
        return i != 0 && e != null && reg.valid(e) ? e : entity{null};
    }
};

// One operation with its random parameters, drawn once and applied to both worlds alike.
struct operation {
    int kind;
    vector3 v;
    scalar size;
    unsigned pick, other, choice;
};

operation draw(std::mt19937 &rng) {
    auto uniform = [&](float a, float b) { return scalar(std::uniform_real_distribution<float>(a, b)(rng)); };
    operation op;
    op.kind = int(rng() % 12);
    op.v = {uniform(-5, 5), uniform(0.5, 5), uniform(-5, 5)};
    op.size = uniform(0.2f, 0.7f);
    op.pick = unsigned(rng());
    op.other = unsigned(rng());
    op.choice = unsigned(rng() % 4);
    return op;
}

void apply(world &w, const operation &op) {
    auto &reg = w.reg;
    auto e = w.body(op.pick), f = w.body(op.other);
    auto dynamic = e != null && reg.all_of<dynamic_tag>(e);
    auto h = op.size;
    switch (op.kind) {
    case 0:
    case 1: {
        rigidbody_def def;
        def.mass = 1 + h;
        def.position = op.v;
        switch (op.choice) {
        case 0:
            def.shape = box_shape{h, h, h};
            break;
        case 1:
            def.shape = sphere_shape{h};
            break;
        case 2:
            def.shape = capsule_shape{h / 2, h};
            break;
        default:
            def.shape = cylinder_shape{h, h / 2};
            break;
        }
        w.bodies.push_back(make_rigidbody(reg, def));
        break;
    }
    case 2:
        if (e != null) {
            reg.destroy(e);
            w.bodies[op.pick % w.bodies.size()] = null;
        }
        break;
    case 3:
        if (dynamic) rigidbody_apply_impulse(reg, e, op.v, vector3_zero);
        break;
    case 4:
        if (dynamic) rigidbody_set_shape(reg, e, box_shape{h, h * scalar(0.7), h});
        break;
    case 5:
        if (e != null) {
            auto kinds = {rigidbody_kind::rb_dynamic, rigidbody_kind::rb_kinematic,
                          rigidbody_kind::rb_static};
            rigidbody_set_kind(reg, e, *(kinds.begin() + op.choice % 3));
        }
        break;
    case 6:
        if (e != null && f != null && e != f && (dynamic || reg.all_of<dynamic_tag>(f)))
            make_constraint<distance_constraint>(reg, e, f,
                                                 [&](distance_constraint &c) { c.distance = 4 * h; });
        break;
    case 7:
        if (e == null) break;
        if (reg.all_of<material>(e))
            reg.remove<material>(e);
        else
            reg.emplace<material>(e);
        break;
    case 8:
        if (!dynamic) break;
        if (reg.all_of<gravity>(e))
            reg.remove<gravity>(e);
        else
            reg.emplace<gravity>(e, vector3{0, op.v.y - 3, 0});
        break;
    case 9:
        if (dynamic) set_center_of_mass(reg, e, {h * scalar(0.3), 0, 0});
        break;
    case 10:
        if (e != null && !reg.all_of<static_tag>(e)) reg.replace<linvel>(e, vector3{op.v.x, 0, op.v.z});
        break;
    default:
        if (e != null && f != null && e != f) exclude_collision(reg, e, f);
        break;
    }
}

class async_differential : public ::testing::TestWithParam<unsigned> {};

TEST_P(async_differential, a_random_program_moves_the_same_in_both_modes) {
    world sequential(execution_mode::sequential), asynchronous(execution_mode::asynchronous);
    std::mt19937 rng(GetParam());
    for (int step = 0; step < 300; ++step) {
        for (auto n = rng() % 3; n > 0; --n) {
            auto op = draw(rng);
            apply(sequential, op);
            apply(asynchronous, op);
        }
        for (auto *w : {&sequential, &asynchronous}) {
            step_simulation(w->reg);
            wait_for_simulation(w->reg);
        }
        ASSERT_EQ(sequential.bodies.size(), asynchronous.bodies.size());
        for (std::size_t i = 0; i < sequential.bodies.size(); ++i) {
            auto a = sequential.bodies[i], b = asynchronous.bodies[i];
            auto alive = a != null && sequential.reg.valid(a);
            ASSERT_EQ(alive, b != null && asynchronous.reg.valid(b)) << "body " << i << " at step " << step;
            if (!alive) continue;
            auto &pa = sequential.reg.get<position>(a), &pb = asynchronous.reg.get<position>(b);
            auto &qa = sequential.reg.get<orientation>(a), &qb = asynchronous.reg.get<orientation>(b);
            ASSERT_EQ(std::memcmp(&pa, &pb, sizeof(pa)), 0)
                << "body " << i << " at step " << step << ": sequential (" << pa.x << ", " << pa.y << ", "
                << pa.z << "), asynchronous (" << pb.x << ", " << pb.y << ", " << pb.z << ")";
            ASSERT_EQ(std::memcmp(&qa, &qb, sizeof(qa)), 0) << "body " << i << " at step " << step;
        }
    }
}

// Before entity members naming destroyed entities were sent as null, 25 of the first 80 seeds
// failed, among them 5, 11, 12, 15 and 16 (a body named in an exclusion list destroyed, and the
// list sent again later).
INSTANTIATE_TEST_SUITE_P(seeds, async_differential, ::testing::Range(1u, 17u));

} // namespace differential
