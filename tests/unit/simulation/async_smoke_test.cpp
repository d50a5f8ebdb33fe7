#include <edyn/edyn.hpp>
#include <gtest/gtest.h>

namespace {

edyn::init_config async_config() {
    edyn::init_config c;
    c.execution_mode = edyn::execution_mode::asynchronous;
    return c;
}

edyn::vector3 run(edyn::init_config config, std::uint64_t &steps) {
    edyn::registry reg;
    edyn::attach(reg, config);
    edyn::rigidbody_def ground;
    ground.kind = edyn::rigidbody_kind::rb_static;
    ground.shape = edyn::plane_shape{{0, 1, 0}, 0};
    edyn::make_rigidbody(reg, ground);
    edyn::rigidbody_def def;
    def.mass = 10;
    def.shape = edyn::box_shape{0.5, 0.5, 0.5};
    def.position = {0, 3, 0};
    auto box = edyn::make_rigidbody(reg, def);
    for (int frame = 0; frame <= 120; ++frame) {
        edyn::update(reg, frame / 60.0);
        edyn::wait_for_simulation(reg);
    }
    steps = edyn::get_step_count(reg);
    auto p = reg.get<edyn::present_position>(box);
    edyn::detach(reg);
    return p;
}

TEST(async_smoke, box_falls) {
    std::uint64_t s0, s1;
    auto a = run(async_config(), s0);
    auto b = run({}, s1);
    EXPECT_EQ(s0, s1);
    EXPECT_EQ(a.y, b.y);
    EXPECT_NEAR(a.y, 0.5, 0.01);
}

} // namespace
