#include "collide_bench_support.hpp"
#include "edyn/collision/collide.hpp"
#include <benchmark/benchmark.h>
#include <vector>

// collide() for the pairs with a cylinder: a resting contact (the common steady state) and a
// cycle over random placements around touching (from overlapping to just apart), which is what
// the narrowphase sees for pairs whose AABBs overlap.
namespace {

using namespace edyn;

const cylinder_shape cylinder{scalar(0.3), scalar(0.5), coordinate_axis::y};
const auto upright = quaternion_identity;
const auto lying = quaternion_axis_angle(vector3_z, half_pi);

void cylinder_cylinder_stacked(benchmark::State &state) {
    bench::run_collide(state, cylinder, cylinder, {{0.1f, 0.995f, 0}, upright, vector3_zero, upright, 0.02f});
}
void cylinder_cylinder_crossed(benchmark::State &state) {
    bench::run_collide(
        state, cylinder, cylinder,
        {{0, 0.595f, 0}, lying, vector3_zero, quaternion_axis_angle(vector3_x, half_pi), 0.02f});
}
void cylinder_cylinder_random(benchmark::State &state) {
    bench::run_collide_random(state, cylinder, cylinder, scalar(1.2), scalar(0.5), scalar(0.95));
}

const box_shape box{{0.5f, 0.3f, 0.4f}};
void cylinder_box_standing(benchmark::State &state) {
    bench::run_collide(state, cylinder, box, {{0.1f, 0.795f, 0}, upright, vector3_zero, upright, 0.02f});
}
void cylinder_box_lying(benchmark::State &state) {
    bench::run_collide(state, cylinder, box, {{0.1f, 0.595f, 0}, lying, vector3_zero, upright, 0.02f});
}
void cylinder_box_random(benchmark::State &state) {
    bench::run_collide_random(state, cylinder, box, scalar(1.3), scalar(0.5), scalar(0.95));
}
void box_cylinder_random(benchmark::State &state) {
    bench::run_collide_random(state, box, cylinder, scalar(1.3), scalar(0.5), scalar(0.95));
}

const capsule_shape capsule{scalar(0.2), scalar(0.4), coordinate_axis::x};
void capsule_cylinder_lying(benchmark::State &state) {
    bench::run_collide(state, capsule, cylinder, {{0.1f, 0.695f, 0}, upright, vector3_zero, upright, 0.02f});
}
void cylinder_capsule_random(benchmark::State &state) {
    bench::run_collide_random(state, cylinder, capsule, scalar(1.2), scalar(0.5), scalar(0.95));
}

const sphere_shape sphere{scalar(0.3)};
void sphere_cylinder_resting(benchmark::State &state) {
    bench::run_collide(state, sphere, cylinder, {{0.1f, 0.795f, 0}, upright, vector3_zero, upright, 0.02f});
}
void cylinder_sphere_random(benchmark::State &state) {
    bench::run_collide_random(state, cylinder, sphere, scalar(0.9), scalar(0.5), scalar(0.95));
}

const plane_shape plane{vector3_y, 0};
void cylinder_plane_standing(benchmark::State &state) {
    bench::run_collide(state, cylinder, plane, {{0, 0.495f, 0}, upright, vector3_zero, upright, 0.02f});
}
void cylinder_plane_tilted(benchmark::State &state) {
    bench::run_collide(state, cylinder, plane,
                       {{0, 0.5f, 0}, quaternion_axis_angle(vector3_x, 0.3f), vector3_zero, upright, 0.02f});
}

} // namespace

BENCHMARK(cylinder_cylinder_stacked);
BENCHMARK(cylinder_cylinder_crossed);
BENCHMARK(cylinder_cylinder_random);
BENCHMARK(cylinder_box_standing);
BENCHMARK(cylinder_box_lying);
BENCHMARK(cylinder_box_random);
BENCHMARK(box_cylinder_random);
BENCHMARK(capsule_cylinder_lying);
BENCHMARK(cylinder_capsule_random);
BENCHMARK(sphere_cylinder_resting);
BENCHMARK(cylinder_sphere_random);
BENCHMARK(cylinder_plane_standing);
BENCHMARK(cylinder_plane_tilted);
