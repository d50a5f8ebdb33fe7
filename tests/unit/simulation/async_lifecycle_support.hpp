#ifndef EDYN_TESTS_UNIT_SIMULATION_ASYNC_LIFECYCLE_SUPPORT_HPP
#define EDYN_TESTS_UNIT_SIMULATION_ASYNC_LIFECYCLE_SUPPORT_HPP

// Scenes, probes and the fixture shared by the asynchronous mode's lifecycle tests.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <edyn/edyn.hpp>
#include <exception>
#include <functional>
#include <gtest/gtest.h>
#include <iterator>
#include <limits>
#include <mutex>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace edyn::async_lifecycle_support {

using namespace edyn;

inline constexpr double frame = 1.0 / 60.0;

inline init_config async_config() { return init_config{execution_mode::asynchronous}; }

inline entity make_ground(registry &reg) {
    rigidbody_def def;
    def.kind = rigidbody_kind::rb_static;
    def.shape = plane_shape{vector3_y, 0};
    return make_rigidbody(reg, def);
}

inline entity make_box(registry &reg, const vector3 &at,
                       const vector3 &half = {scalar(0.5), scalar(0.5), scalar(0.5)},
                       rigidbody_kind kind = rigidbody_kind::rb_dynamic) {
    rigidbody_def def;
    def.kind = kind;
    def.position = at;
    def.shape = box_shape{half.x, half.y, half.z};
    return make_rigidbody(reg, def);
}

inline entity make_ball(registry &reg, const vector3 &at, scalar radius,
                        rigidbody_kind kind = rigidbody_kind::rb_dynamic) {
    rigidbody_def def;
    def.kind = kind;
    def.position = at;
    def.shape = sphere_shape{radius};
    return make_rigidbody(reg, def);
}

inline std::vector<entity> constraint_entities_of(const registry &reg, entity body) {
    std::vector<constraint_ref> refs;
    constraints_of(reg, body, refs);
    std::vector<entity> result;
    for (auto &ref : refs)
        result.push_back(ref.constraint);
    return result;
}

inline std::size_t count_constraints(registry &reg) {
    return reg.view<point_constraint>().size() + reg.view<distance_constraint>().size() +
           reg.view<hinge_constraint>().size() + reg.view<null_constraint>().size();
}

// Receives raycast_async's and query_aabb_async's replies (on the main thread).
struct reply_catcher {
    int rays{0};
    raycast_result ray;
    int queries{0};
    query_aabb_result query;

    void on_ray(raycast_id_type, const raycast_result &result, vector3, vector3) {
        ++rays;
        ray = result;
    }
    void on_query(query_aabb_id_type, const query_aabb_result &result) {
        ++queries;
        query = result;
    }
};

// The rigid bodies the worker has, as main entities (asked of its broadphase), ground excluded.
inline std::vector<entity> worker_bodies(registry &reg, entity ground) {
    reply_catcher catcher;
    constexpr scalar far = scalar(1e6);
    query_aabb_async(reg, AABB{{-far, -far, -far}, {far, far, far}},
                     query_aabb_delegate_type{connect_arg<&reply_catcher::on_query>, catcher});
    wait_for_simulation(reg);
    EXPECT_EQ(catcher.queries, 1) << "query_aabb_async replies delivered by wait_for_simulation";
    auto result = catcher.query.entities;
    std::erase(result, ground);
    std::sort(result.begin(), result.end());
    return result;
}

// Height of the first surface the worker has on the vertical line through (x, z), cast down
// from `from_y`, with the body hit; NaN when nothing is hit.
inline scalar worker_surface_height(registry &reg, scalar x, scalar z, scalar from_y, entity *hit = nullptr) {
    reply_catcher catcher;
    vector3 p0{x, from_y, z}, p1{x, -from_y, z};
    raycast_async(reg, p0, p1, raycast_delegate_type{connect_arg<&reply_catcher::on_ray>, catcher});
    wait_for_simulation(reg);
    EXPECT_EQ(catcher.rays, 1) << "raycast_async replies delivered by wait_for_simulation";
    if (hit) *hit = catcher.ray.entity;
    if (!catcher.ray.hit()) return std::numeric_limits<scalar>::quiet_NaN();
    return lerp(p0, p1, catcher.ray.fraction).y;
}

// The body's up axis in world space (y of it is the cosine of its tilt).
inline vector3 up_axis(registry &reg, entity e) { return rotate(reg.get<orientation>(e), vector3_y); }

// Step callback state: the callback runs in the worker, the test reads it after waiting.
inline std::atomic<int> callback_calls{0};
inline std::atomic<int> throw_on_call{-1};

inline void throwing_pre_step(registry &) {
    auto n = ++callback_calls;
    if (n == throw_on_call.load())
        throw std::runtime_error("pre-step callback failed on call " + std::to_string(n));
}

// Runs `fn` on a thread of its own and returns how long it took. A hang cannot be joined nor
// left behind, so past `limit` it is reported and the program aborts (instead of hanging the
// whole test run).
inline double run_with_deadline(const std::function<void()> &fn, std::chrono::seconds limit,
                                const char *what) {
    std::mutex mutex;
    std::condition_variable finished;
    bool done = false;
    std::exception_ptr error;
    auto start = std::chrono::steady_clock::now();
    std::thread runner([&] {
        try {
            fn();
        } catch (...) {
            error = std::current_exception();
        }
        std::lock_guard lock(mutex);
        done = true;
        finished.notify_one();
    });
    {
        std::unique_lock lock(mutex);
        if (!finished.wait_for(lock, limit, [&] { return done; })) {
            std::fprintf(stderr, "%s: still running after %lld s, hung\n", what,
                         static_cast<long long>(limit.count()));
            std::abort();
        }
    }
    runner.join();
    if (error) std::rethrow_exception(error);
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct async_lifecycle : ::testing::Test {
    registry reg;
    entity ground{null};
    double t{0};

    void TearDown() override {
        set_callbacks_off();
        if (is_attached(reg)) detach(reg);
    }

    void set_callbacks_off() {
        if (!is_attached(reg)) return;
        set_pre_step_callback(reg, nullptr);
        set_post_step_callback(reg, nullptr);
    }

    // Attaches in asynchronous mode with a ground plane and starts the caller's clock.
    void start() {
        attach(reg, async_config());
        ground = make_ground(reg);
        update(reg, t);
    }

    // `frames` updates a frame apart, each waited for: one step each, so that the physics the
    // test then measures ran for a known time (a worker left behind drops time).
    void run_frames(int frames) {
        for (int i = 0; i < frames; ++i) {
            t += frame;
            update(reg, t);
            wait_for_simulation(reg);
        }
    }

    // One update whose step the worker runs while the caller goes on (not waited for).
    void update_without_waiting() {
        t += frame;
        update(reg, t);
    }

    vector3 pos(entity e) { return reg.get<position>(e); }
};

} // namespace edyn::async_lifecycle_support

#endif // EDYN_TESTS_UNIT_SIMULATION_ASYNC_LIFECYCLE_SUPPORT_HPP
