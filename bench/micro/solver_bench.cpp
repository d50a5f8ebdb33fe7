#include "edyn/constraints/contact_solver.hpp"
#include <algorithm>
#include <benchmark/benchmark.h>
#include <cstdint>
#include <random>
#include <vector>

namespace {

using edyn::scalar;
using edyn::vector3;

// Boxes resting on one another like a large pile: each contact joins two random bodies (one in
// eight touches the ground, the static body) with four points at the corners of a face. Three
// rows per point (normal and two friction directions) give the row count asked for, spread over
// memory as a real pile's bodies are.
struct contact_set {
    std::vector<edyn::solver_body> bodies;
    edyn::contact_solver_set contacts;

    contact_set(std::size_t rows, unsigned seed) {
        constexpr std::size_t rows_per_contact = 3 * edyn::contact_solver_constraint::max_points;
        auto num_contacts = (rows + rows_per_contact - 1) / rows_per_contact;
        auto num_bodies = std::max<std::size_t>(2, num_contacts / 2);
        std::mt19937 rng(seed);
        std::uniform_int_distribution<std::uint32_t> body(1, static_cast<std::uint32_t>(num_bodies));
        std::uniform_real_distribution<scalar> speed(-1, 1);

        bodies.resize(num_bodies + 1); // index 0: the static body
        for (std::size_t i = 1; i < bodies.size(); ++i) {
            auto &b = bodies[i];
            b.inv_mass = 1;
            b.inv_inertia = edyn::matrix3x3_rows({6, 0, 0}, {0, 6, 0}, {0, 0, 6}); // unit box
            b.linvel = {speed(rng), speed(rng), speed(rng)};
            b.angvel = {speed(rng), speed(rng), speed(rng)};
            b.acceleration = {0, scalar(-9.8), 0};
        }

        const scalar corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (std::size_t k = 0; k < num_contacts; ++k) {
            edyn::contact_solver_constraint c;
            c.body[0] = body(rng);
            c.body[1] = rng() % 8 == 0 ? edyn::static_solver_body : body(rng);
            if (c.body[1] == c.body[0]) c.body[1] = edyn::static_solver_body;
            c.normal = edyn::vector3_y;
            c.friction = scalar(0.6);
            auto *points = contacts.add(c, edyn::contact_solver_constraint::max_points);
            for (std::uint32_t i = 0; i < edyn::contact_solver_constraint::max_points; ++i) {
                auto &p = points[i];
                p.rA = {corners[i][0] / 2, scalar(-0.5), corners[i][1] / 2};
                p.rB = {corners[i][0] / 2, scalar(0.5), corners[i][1] / 2};
                p.normal = edyn::vector3_y;
                p.adjusted_separation = scalar(-0.002) - edyn::dot(p.normal, p.rA - p.rB);
            }
        }
        edyn::prepare_contacts(contacts, bodies);
    }
};

// One biased Gauss-Seidel pass of the soft-step contact solver (a sub-step's iteration).
void solver_iteration(benchmark::State &state) {
    contact_set set(static_cast<std::size_t>(state.range(0)), 5);
    edyn::contact_solver_settings settings;
    auto h = scalar(1) / scalar(60 * 4);
    edyn::stage_queue queue;
    for (auto _ : state) {
        edyn::solve_contacts(set.contacts, set.bodies, h, 0, settings, true, queue);
        queue.run(nullptr);
        benchmark::DoNotOptimize(set.bodies.data());
        benchmark::ClobberMemory();
    }
    auto rows = set.contacts.points.size() * 3;
    state.counters["rows"] = static_cast<double>(rows);
    state.counters["rows/s"] =
        benchmark::Counter(static_cast<double>(rows), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(solver_iteration)->Arg(1000)->Arg(10000)->Arg(100000);

// A relax pass: the same rows without the push-out bias.
void solver_relax_iteration(benchmark::State &state) {
    contact_set set(static_cast<std::size_t>(state.range(0)), 5);
    edyn::contact_solver_settings settings;
    auto h = scalar(1) / scalar(60 * 4);
    edyn::stage_queue queue;
    for (auto _ : state) {
        edyn::solve_contacts(set.contacts, set.bodies, h, 0, settings, false, queue);
        queue.run(nullptr);
        benchmark::DoNotOptimize(set.bodies.data());
        benchmark::ClobberMemory();
    }
    state.counters["rows/s"] = benchmark::Counter(static_cast<double>(set.contacts.points.size() * 3),
                                                  benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(solver_relax_iteration)->Arg(10000)->Arg(100000);

// Warm starting the same rows, done once per sub-step before the iterations.
void solver_warm_start(benchmark::State &state) {
    contact_set set(static_cast<std::size_t>(state.range(0)), 5);
    for (auto &p : set.contacts.points)
        p.normal_impulse = scalar(0.01);
    edyn::stage_queue queue;
    for (auto _ : state) {
        edyn::warm_start_contacts(set.contacts, set.bodies, queue);
        queue.run(nullptr);
        benchmark::DoNotOptimize(set.bodies.data());
        benchmark::ClobberMemory();
    }
}
BENCHMARK(solver_warm_start)->Arg(10000)->Arg(100000);

} // namespace
