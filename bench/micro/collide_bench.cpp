#include "collide_bench_support.hpp"
#include "edyn/collision/collide.hpp"
#include <benchmark/benchmark.h>

// One benchmark per collide() pair of primitive shapes, in typical contact configurations.

namespace {

using namespace edyn;

using bench::run_collide;

void box_box_resting(benchmark::State &state) {
    collision_context ctx{
        {0, 0, 0}, quaternion_identity, {0.1, 0.995, -0.05}, quaternion_axis_angle(vector3_y, 0.3), 0.02};
    run_collide(state, box_shape{0.5, 0.5, 0.5}, box_shape{0.5, 0.5, 0.5}, ctx);
}
BENCHMARK(box_box_resting);

void box_box_rotated(benchmark::State &state) {
    collision_context ctx{{0, 0, 0},
                          quaternion_axis_angle(normalize(vector3{1, 2, 3}), 0.7),
                          {0.3, 0.8, 0.2},
                          quaternion_axis_angle(normalize(vector3{-2, 1, 1}), 1.1),
                          0.02};
    run_collide(state, box_shape{0.5, 0.4, 0.6}, box_shape{0.3, 0.5, 0.4}, ctx);
}
BENCHMARK(box_box_rotated);

void box_box_edge_edge(benchmark::State &state) {
    collision_context ctx{{0, 0, 0},
                          quaternion_axis_angle(vector3_z, 0.785398f),
                          {0, 1.404f, 0},
                          quaternion_axis_angle(vector3_x, 0.785398f),
                          0.02};
    run_collide(state, box_shape{0.5, 0.5, 0.5}, box_shape{0.5, 0.5, 0.5}, ctx);
}
BENCHMARK(box_box_edge_edge);

void box_box_apart_corner(benchmark::State &state) {
    // Separated within the threshold corner to corner: takes the exact closest-pair path.
    collision_context ctx{{0, 0, 0}, quaternion_identity, {1.005, 1.005, 1.005}, quaternion_identity, 0.02};
    run_collide(state, box_shape{0.5, 0.5, 0.5}, box_shape{0.5, 0.5, 0.5}, ctx);
}
BENCHMARK(box_box_apart_corner);

void sphere_sphere(benchmark::State &state) {
    collision_context ctx{{0, 0, 0}, quaternion_identity, {0.3, 0.85, 0.1}, quaternion_identity, 0.02};
    run_collide(state, sphere_shape{0.5}, sphere_shape{0.4}, ctx);
}
BENCHMARK(sphere_sphere);

void sphere_box(benchmark::State &state) {
    collision_context ctx{{0.2, 0.99, 0.1},
                          quaternion_identity,
                          {0, 0, 0},
                          quaternion_axis_angle(normalize(vector3{1, 1, 0}), 0.2),
                          0.02};
    run_collide(state, sphere_shape{0.5}, box_shape{0.5, 0.5, 0.5}, ctx);
}
BENCHMARK(sphere_box);

void sphere_capsule(benchmark::State &state) {
    collision_context ctx{
        {0.2, 0.69, 0.1}, quaternion_identity, {0, 0, 0}, quaternion_axis_angle(vector3_y, 0.5), 0.02};
    run_collide(state, sphere_shape{0.5}, capsule_shape{0.2, 1, coordinate_axis::x}, ctx);
}
BENCHMARK(sphere_capsule);

void sphere_plane(benchmark::State &state) {
    collision_context ctx{{0.2, 0.49, 0.1}, quaternion_identity, {}, quaternion_identity, 0.02};
    run_collide(state, sphere_shape{0.5}, plane_shape{vector3_y, 0}, ctx);
}
BENCHMARK(sphere_plane);

void capsule_capsule_crossing(benchmark::State &state) {
    collision_context ctx{
        {0, 0, 0}, quaternion_identity, {0.2, 0.39, 0.1}, quaternion_axis_angle(vector3_y, 1.2), 0.02};
    run_collide(state, capsule_shape{0.2, 1, coordinate_axis::x}, capsule_shape{0.2, 1, coordinate_axis::x},
                ctx);
}
BENCHMARK(capsule_capsule_crossing);

void capsule_capsule_parallel(benchmark::State &state) {
    collision_context ctx{{0, 0, 0}, quaternion_identity, {0.5, 0.39, 0}, quaternion_identity, 0.02};
    run_collide(state, capsule_shape{0.2, 1, coordinate_axis::x}, capsule_shape{0.2, 1, coordinate_axis::x},
                ctx);
}
BENCHMARK(capsule_capsule_parallel);

void capsule_box_lying(benchmark::State &state) {
    collision_context ctx{
        {0.1, 0.695, 0.2}, quaternion_axis_angle(vector3_y, 0.4), {0, 0, 0}, quaternion_identity, 0.02};
    run_collide(state, capsule_shape{0.2, 0.4, coordinate_axis::x}, box_shape{1, 0.5, 1}, ctx);
}
BENCHMARK(capsule_box_lying);

void capsule_box_penetrating(benchmark::State &state) {
    collision_context ctx{
        {0.95, 0.45, 0}, quaternion_axis_angle(vector3_z, -0.785398f), {0, 0, 0}, quaternion_identity, 0.02};
    run_collide(state, capsule_shape{0.2, 0.5, coordinate_axis::x}, box_shape{1, 0.5, 1}, ctx);
}
BENCHMARK(capsule_box_penetrating);

void capsule_plane(benchmark::State &state) {
    collision_context ctx{
        {0, 0.195, 0}, quaternion_axis_angle(vector3_y, 0.3), {}, quaternion_identity, 0.02};
    run_collide(state, capsule_shape{0.2, 1, coordinate_axis::x}, plane_shape{vector3_y, 0}, ctx);
}
BENCHMARK(capsule_plane);

void box_plane(benchmark::State &state) {
    collision_context ctx{
        {0, 0.495, 0}, quaternion_axis_angle(vector3_y, 0.3), {}, quaternion_identity, 0.02};
    run_collide(state, box_shape{0.5, 0.5, 0.5}, plane_shape{vector3_y, 0}, ctx);
}
BENCHMARK(box_plane);

} // namespace
