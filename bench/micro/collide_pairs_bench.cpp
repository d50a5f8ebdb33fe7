#include "collide_bench_support.hpp"
#include "edyn/collision/collide.hpp"
#include <array>
#include <benchmark/benchmark.h>
#include <string>

// Every collide() pair through the variant dispatcher, B resting on top of A (overlapping by
// 1 cm and tilted a little), so that each pair has at least one figure, named pair/<A>_<B>.
// The hand-placed benchmarks in the other files cover more configurations of the common pairs.

namespace {

using namespace edyn;

shapes_variant_t sample_shape(std::size_t index) {
    switch (index) {
    case 0:
        return plane_shape{vector3_y, 0};
    case 1:
        return sphere_shape{0.5};
    case 2:
        return cylinder_shape{0.5, 0.5, coordinate_axis::x};
    case 3:
        return capsule_shape{0.3, 0.5, coordinate_axis::x};
    case 4:
        return box_shape{0.5, 0.4, 0.6};
    case 5: {
        // An icosahedron of circumradius 0.6.
        const scalar g = scalar(1.618034);
        std::vector<vector3> points;
        for (auto s : {scalar(-1), scalar(1)})
            for (auto t : {scalar(-1), scalar(1)}) {
                points.push_back(vector3{0, s, t * g} * scalar(0.316));
                points.push_back(vector3{s, t * g, 0} * scalar(0.316));
                points.push_back(vector3{s * g, 0, t} * scalar(0.316));
            }
        return polyhedron_shape{points};
    }
    default: {
        compound_shape compound;
        compound.add_shape(box_shape{0.3, 0.3, 0.3}, {-0.4, 0, 0}, quaternion_identity);
        compound.add_shape(sphere_shape{0.35}, {0.4, 0, 0}, quaternion_identity);
        compound.add_shape(capsule_shape{0.2, 0.3, coordinate_axis::z}, {0, 0.1, 0.4}, quaternion_identity);
        compound.add_shape(cylinder_shape{0.25, 0.2, coordinate_axis::y}, {0, 0, -0.4}, quaternion_identity);
        compound.finish();
        return compound;
    }
    }
}

const char *shape_name(std::size_t index) {
    constexpr std::array<const char *, 7> names{"plane", "sphere",     "cylinder", "capsule",
                                                "box",   "polyhedron", "compound"};
    return names[index];
}

void run(benchmark::State &state, std::size_t ia, std::size_t ib) {
    auto a = sample_shape(ia), b = sample_shape(ib);
    auto ornB = quaternion_axis_angle(normalize(vector3{1, 0, 1}), scalar(0.1));
    // Bisect B's height for an overlap of 1 cm: curved shapes do not touch where their AABBs do.
    collision_context ctx{vector3_zero, quaternion_identity, vector3_zero, ornB, scalar(0.02)};
    auto deepest = [&](scalar height) {
        ctx.posB = {0.05, height, -0.03};
        collision_result result;
        collide(a, b, ctx, result);
        auto d = large_scalar;
        for (std::size_t i = 0; i < result.num_points; ++i)
            d = std::min(d, result.point[i].distance);
        return d;
    };
    scalar low = -2, high = 4;
    for (int i = 0; i < 40; ++i) {
        auto mid = (low + high) / 2;
        (deepest(mid) < scalar(-0.01) ? low : high) = mid;
    }
    ctx.posB.y = low;
    bench::run_collide(state, a, b, ctx);
}

const bool registered = [] {
    for (std::size_t ia = 0; ia < 7; ++ia) {
        for (std::size_t ib = std::max<std::size_t>(ia, 1); ib < 7; ++ib) {
            auto name = std::string("pair/") + shape_name(ia) + "_" + shape_name(ib);
            benchmark::RegisterBenchmark(name.c_str(),
                                         [ia, ib](benchmark::State &state) { run(state, ia, ib); });
        }
    }
    return true;
}();

} // namespace
