// The stacking bar: a 20-row pyramid and a 30-box tower stand still for 10 s.
#include "behaviour_support.hpp"
#include <edyn_scenes/scenes.hpp>

using namespace edyn;
using stacking = edyn::test::world_fixture;

TEST_F(stacking, pyramid_of_210_boxes_stands_for_ten_seconds) {
    scenes::make_ground(reg);
    auto boxes = scenes::make_pyramid(reg, 20);
    ASSERT_EQ(boxes.size(), 210u);
    auto top = boxes.back();
    auto start = pos(top);
    run_for(10);
    auto moved = length(pos(top) - start);
    EXPECT_LT(moved, scalar(0.01)) << "top box moved " << moved << " m";
    for (auto e : boxes)
        ASSERT_TRUE(isfinite(pos(e)));
}

TEST_F(stacking, tower_of_30_boxes_stands_for_ten_seconds) {
    scenes::make_ground(reg);
    auto boxes = scenes::make_tower(reg, 30);
    auto start = pos(boxes.back());
    run_for(10);
    // Standing: every box still rests on the one below it, and the top has neither fallen nor
    // sunk by more than the contacts' compression under the tower's weight.
    for (std::size_t i = 1; i < boxes.size(); ++i) {
        auto below = pos(boxes[i - 1]), above = pos(boxes[i]);
        auto offset = length(vector3{above.x - below.x, 0, above.z - below.z});
        EXPECT_LT(offset, scalar(0.01)) << "box " << i << " is off the one below by " << offset << " m";
        EXPECT_NEAR(above.y - below.y, 1, scalar(0.01)) << "box " << i;
    }
    auto top = pos(boxes.back());
    EXPECT_NEAR(top.y, start.y, scalar(0.05)) << "top box sank " << start.y - top.y << " m";
    auto sideways = length(vector3{top.x - start.x, 0, top.z - start.z});
    EXPECT_LT(sideways, scalar(0.01)) << "top box crept sideways by " << sideways << " m";
    // Still, so it sleeps.
    EXPECT_TRUE(reg.all_of<sleeping_tag>(boxes.back()));
}

// A pyramid four times the size: the top settles by the springs' compression and does not creep.
TEST_F(stacking, pyramid_of_820_boxes_does_not_creep) {
    scenes::make_ground(reg);
    auto boxes = scenes::make_pyramid(reg, 40);
    auto top = boxes.back();
    auto start = pos(top);
    run_for(10);
    auto now = pos(top);
    auto sideways = length(vector3{now.x - start.x, 0, now.z - start.z});
    EXPECT_LT(sideways, scalar(0.02)) << "top box crept sideways by " << sideways << " m";
    EXPECT_NEAR(now.y, start.y, scalar(0.03)) << "top box sank " << start.y - now.y << " m";
}
