#include "collide_bench_support.hpp"
#include "edyn/collision/collide.hpp"
#include "edyn/math/math.hpp"
#include <benchmark/benchmark.h>

// collide() with compounds at resting contact, the case the narrowphase meets every step.
namespace {

using namespace edyn;

// Two bars meeting at a right angle (an L lying flat), tops at y = 0.25.
compound_shape two_boxes() {
    compound_shape c;
    c.add_shape(box_shape{{1, 0.25, 0.25}});
    c.add_shape(box_shape{{0.25, 0.25, 1}}, {1.25, 0, 0.75});
    c.finish();
    return c;
}

// 4 x 4 blocks (past max_children_without_tree: the tree path), tops at y = 0.25.
compound_shape sixteen_boxes() {
    compound_shape c;
    for (int ix = 0; ix < 4; ++ix) {
        for (int iz = 0; iz < 4; ++iz) {
            c.add_shape(box_shape{{0.25, 0.25, 0.25}},
                        {scalar(ix) - scalar(1.5), 0, scalar(iz) - scalar(1.5)});
        }
    }
    c.finish();
    return c;
}

// A box of half size 0.2 sunk 1 cm into the top of the compound at `top`, slightly turned.
void run_compound_box(benchmark::State &state, const compound_shape &compound, const vector3 &top) {
    auto box = box_shape{{0.2, 0.2, 0.2}};
    collision_context ctx{vector3_zero, quaternion_identity, top + vector3{0, scalar(0.19), 0},
                          quaternion_axis_angle(vector3_y, scalar(0.3)), scalar(0.02)};
    bench::run_collide(state, compound, box, ctx);
}

void compound_2_boxes_vs_box(benchmark::State &state) {
    run_compound_box(state, two_boxes(), {1.25, 0.25, 0.75});
}

void compound_16_boxes_vs_box(benchmark::State &state) {
    run_compound_box(state, sixteen_boxes(), {0.5, 0.25, 0.5});
}

// The L lying across the grid of blocks, sunk 1 cm: several pairs of children touch.
void compound_vs_compound(benchmark::State &state) {
    auto l = two_boxes();
    auto grid = sixteen_boxes();
    collision_context ctx{{-0.4, scalar(0.49), -0.3},
                          quaternion_axis_angle(vector3_y, scalar(0.2)),
                          vector3_zero,
                          quaternion_identity,
                          scalar(0.02)};
    bench::run_collide(state, l, grid, ctx);
}

} // namespace

BENCHMARK(compound_2_boxes_vs_box);
BENCHMARK(compound_16_boxes_vs_box);
BENCHMARK(compound_vs_compound);
