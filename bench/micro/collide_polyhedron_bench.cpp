#include "collide_bench_support.hpp"
#include "edyn/collision/collide.hpp"
#include <benchmark/benchmark.h>
#include <cmath>
#include <vector>

// collide() for the pairs with a polyhedron: resting contacts (the common steady state) and a
// cycle over random placements around touching (from overlapping to just apart), which is what
// the narrowphase sees for pairs whose AABBs overlap. Box-shaped hulls next to the same pairs
// as boxes give the cost of generality; 20-vertex hulls (36 faces, 54 edges) a typical convex
// decomposition piece.
namespace {

using namespace edyn;

polyhedron_shape box_hull(const vector3 &he) {
    std::vector<vector3> points;
    for (int i = 0; i < 8; ++i) {
        points.push_back({i & 1 ? -he.x : he.x, i & 2 ? -he.y : he.y, i & 4 ? -he.z : he.z});
    }
    return polyhedron_shape(points);
}

// 20 points spread over an ellipsoid, all of them vertices of the hull.
polyhedron_shape hull20() {
    std::vector<vector3> points;
    for (int i = 0; i < 20; ++i) {
        auto y = 1 - 2 * (scalar(i) + scalar(0.5)) / 20;
        auto rho = std::sqrt(1 - y * y);
        auto phi = scalar(i) * scalar(2.399963229728653);
        points.push_back(
            {rho * std::cos(phi) * scalar(0.5), y * scalar(0.4), rho * std::sin(phi) * scalar(0.45)});
    }
    return polyhedron_shape(points);
}

const vector3 cube_he{0.5f, 0.3f, 0.4f};
const box_shape cube_box{cube_he};
const auto cube = box_hull(cube_he);
const auto hull = hull20();
const auto turn = quaternion_axis_angle(vector3_y, 0.3f);
// A resting 5 mm into the other's top face, turned about the vertical.
const collision_context stacked{{0.1f, 0.595f, 0}, turn, vector3_zero, quaternion_identity, 0.02f};

void polyhedron_polyhedron_cube_resting(benchmark::State &state) {
    bench::run_collide(state, cube, cube, stacked);
}
void polyhedron_polyhedron_cube_random(benchmark::State &state) {
    bench::run_collide_random(state, cube, cube, scalar(1.1), scalar(0.7), scalar(1.05));
}
void polyhedron_polyhedron_hull20_resting(benchmark::State &state) {
    // The hull's lowest vertex region on the other's top: a vertex or edge contact.
    bench::run_collide(state, hull, hull,
                       {{0.05f, 0.755f, 0}, turn, vector3_zero, quaternion_identity, 0.02f});
}
void polyhedron_polyhedron_hull20_random(benchmark::State &state) {
    bench::run_collide_random(state, hull, hull, scalar(0.85), scalar(0.7), scalar(1.05));
}
// The same resting and random pairs as boxes, for reference.
void polyhedron_reference_box_box_resting(benchmark::State &state) {
    bench::run_collide(state, cube_box, cube_box, stacked);
}
void polyhedron_reference_box_box_random(benchmark::State &state) {
    bench::run_collide_random(state, cube_box, cube_box, scalar(1.1), scalar(0.7), scalar(1.05));
}

void polyhedron_box_cube_resting(benchmark::State &state) {
    bench::run_collide(state, cube, cube_box, stacked);
}
void polyhedron_box_hull20_random(benchmark::State &state) {
    bench::run_collide_random(state, hull, cube_box, scalar(0.95), scalar(0.7), scalar(1.05));
}

const sphere_shape ball{0.3f};
void polyhedron_sphere_hull20_resting(benchmark::State &state) {
    bench::run_collide(state, hull, ball,
                       {vector3_zero, quaternion_identity, {0.05f, 0.67f, 0}, quaternion_identity, 0.02f});
}
void polyhedron_sphere_hull20_random(benchmark::State &state) {
    bench::run_collide_random(state, hull, ball, scalar(0.75), scalar(0.7), scalar(1.05));
}

const plane_shape ground{vector3_y, 0};
void polyhedron_plane_cube_resting(benchmark::State &state) {
    bench::run_collide(state, cube, ground, {{0, 0.295f, 0}, turn, vector3_zero, quaternion_identity, 0.02f});
}
void polyhedron_plane_hull20_random(benchmark::State &state) {
    auto placements = bench::random_placements(scalar(0.4), scalar(0.7), scalar(1.05), 9);
    std::size_t i = 0, points = 0;
    for (auto _ : state) {
        collision_result result;
        // Placements around the plane: A's position from the random set, B (the plane) fixed.
        auto ctx = placements[i];
        ctx.posA.y = std::abs(ctx.posA.y);
        collide(hull, ground, ctx, result);
        points += result.num_points;
        benchmark::DoNotOptimize(result);
        i = (i + 1) % placements.size();
    }
    state.counters["points"] = benchmark::Counter(double(points), benchmark::Counter::kAvgIterations);
}

BENCHMARK(polyhedron_polyhedron_cube_resting);
BENCHMARK(polyhedron_polyhedron_cube_random);
BENCHMARK(polyhedron_polyhedron_hull20_resting);
BENCHMARK(polyhedron_polyhedron_hull20_random);
BENCHMARK(polyhedron_reference_box_box_resting);
BENCHMARK(polyhedron_reference_box_box_random);
BENCHMARK(polyhedron_box_cube_resting);
BENCHMARK(polyhedron_box_hull20_random);
BENCHMARK(polyhedron_sphere_hull20_resting);
BENCHMARK(polyhedron_sphere_hull20_random);
BENCHMARK(polyhedron_plane_cube_resting);
BENCHMARK(polyhedron_plane_hull20_random);

} // namespace
