// A step of a world that stopped growing allocates nothing: the solver's and the narrowphase's
// scratch memory is reused from step to step. This executable replaces the global operator new
// to count allocations, which is why it is one of its own.
#include <atomic>
#include <cstdlib>
#include <edyn/edyn.hpp>
#include <edyn_scenes/scenes.hpp>
#include <gtest/gtest.h>
#include <new>
#include <vector>

// Where GCC inlines the replaced delete below into a test's `new`, it sees std::free paired with
// operator new and warns of a mismatch (at -O1, as the sanitizer builds compile). Both ends are
// this file's: the replaced new allocates with malloc.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif

namespace {

std::atomic<bool> counting{false};
std::atomic<std::size_t> allocations{0};

void *allocate(std::size_t size) {
    if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1, std::memory_order_relaxed);
    if (size == 0) size = 1;
    if (auto *p = std::malloc(size)) return p;
    throw std::bad_alloc();
}

void *allocate_aligned(std::size_t size, std::align_val_t alignment) {
    if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1, std::memory_order_relaxed);
    auto align = static_cast<std::size_t>(alignment);
    size = (size + align - 1) / align * align;
    if (auto *p = std::aligned_alloc(align, size == 0 ? align : size)) return p;
    throw std::bad_alloc();
}

} // namespace

void *operator new(std::size_t size) { return allocate(size); }
void *operator new[](std::size_t size) { return allocate(size); }
void *operator new(std::size_t size, std::align_val_t alignment) { return allocate_aligned(size, alignment); }
void *operator new[](std::size_t size, std::align_val_t alignment) {
    return allocate_aligned(size, alignment);
}
// The non-throwing forms too (std::stable_sort's buffer uses them), so that every new and
// delete in the program agree on the allocator.
void *operator new(std::size_t size, const std::nothrow_t &) noexcept {
    try {
        return allocate(size);
    } catch (...) {
        return nullptr;
    }
}
void *operator new[](std::size_t size, const std::nothrow_t &) noexcept {
    try {
        return allocate(size);
    } catch (...) {
        return nullptr;
    }
}
void *operator new(std::size_t size, std::align_val_t alignment, const std::nothrow_t &) noexcept {
    try {
        return allocate_aligned(size, alignment);
    } catch (...) {
        return nullptr;
    }
}
void *operator new[](std::size_t size, std::align_val_t alignment, const std::nothrow_t &) noexcept {
    try {
        return allocate_aligned(size, alignment);
    } catch (...) {
        return nullptr;
    }
}
void operator delete(void *p, const std::nothrow_t &) noexcept { std::free(p); }
void operator delete[](void *p, const std::nothrow_t &) noexcept { std::free(p); }
void operator delete(void *p, std::align_val_t, const std::nothrow_t &) noexcept { std::free(p); }
void operator delete[](void *p, std::align_val_t, const std::nothrow_t &) noexcept { std::free(p); }
void operator delete(void *p) noexcept { std::free(p); }
void operator delete[](void *p) noexcept { std::free(p); }
void operator delete(void *p, std::size_t) noexcept { std::free(p); }
void operator delete[](void *p, std::size_t) noexcept { std::free(p); }
void operator delete(void *p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void *p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void *p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void *p, std::size_t, std::align_val_t) noexcept { std::free(p); }

namespace edyn {
namespace {

// Keeps `bodies` awake (asleep, a step would skip the work being measured), lets them settle
// for 300 steps and counts the allocations of 100 more.
std::size_t allocations_in_100_steps_after_settling(registry &reg, const std::vector<entity> &bodies) {
    for (auto e : bodies)
        reg.emplace<sleeping_disabled_tag>(e);
    for (int i = 0; i < 300; ++i)
        step_simulation(reg);

    allocations = 0;
    counting = true;
    for (int i = 0; i < 100; ++i)
        step_simulation(reg);
    counting = false;
    return allocations.load();
}

// A settled, awake 1,024-body pile: the bodies keep touching, sliding a little and trading
// contact points, but the world no longer grows.
std::size_t allocations_per_100_settled_steps(const init_config &config) {
    registry reg;
    attach(reg, config);
    scenes::make_ground(reg);
    auto bodies = scenes::make_pile(reg, 1024, 16, 2, scenes::pile_shapes::with_polyhedra);
    auto count = allocations_in_100_steps_after_settling(reg, bodies);
    detach(reg);
    return count;
}

TEST(step_allocation, a_settled_pile_steps_without_allocating) {
    EXPECT_EQ(allocations_per_100_settled_steps(init_config{execution_mode::sequential}), 0u)
        << "allocations in 100 steps (sequential)";
}

TEST(step_allocation, a_settled_pile_steps_without_allocating_on_worker_threads) {
    init_config config;
    config.execution_mode = execution_mode::sequential_multithreaded;
    config.num_worker_threads = 2;
    config.min_parallel_bodies = 0; // the pile is below the default threshold
    EXPECT_EQ(allocations_per_100_settled_steps(config), 0u) << "allocations in 100 steps (2 threads)";
}

// The same on a mesh: 100 mixed bodies (boxes, spheres, capsules, rocks) settled on a flat
// 20,000-triangle grid (on hills they would keep sliding into new contacts and pages), and on the
// same grid as a paged mesh whose pages stay loaded.
std::size_t allocations_per_100_settled_steps_on_terrain(bool paged) {
    registry reg;
    attach(reg, init_config{execution_mode::sequential});
    scenes::mesh_pile_terrain terrain;
    terrain.paged = paged;
    terrain.page_size = 500;
    terrain.amplitude = 0;
    auto scene = scenes::make_mesh_pile(reg, 100, 10, 1, terrain);
    auto count = allocations_in_100_steps_after_settling(reg, scene.bodies);
    // Resting on the grid, not fallen through it or off it.
    for (auto e : scene.bodies) {
        auto y = reg.get<position>(e).y;
        EXPECT_TRUE(y > 0 && y < 1) << "body " << to_index(e) << " at height " << y;
    }
    EXPECT_GE(reg.storage<contact_manifold>().size(), scene.bodies.size()) << "every body touches the grid";
    detach(reg);
    return count;
}

TEST(step_allocation, a_pile_settled_on_a_mesh_terrain_steps_without_allocating) {
    EXPECT_EQ(allocations_per_100_settled_steps_on_terrain(false), 0u) << "allocations in 100 steps";
}

TEST(step_allocation, a_pile_settled_on_a_paged_terrain_steps_without_allocating) {
    EXPECT_EQ(allocations_per_100_settled_steps_on_terrain(true), 0u) << "allocations in 100 steps";
}

TEST(step_allocation, the_counter_sees_allocations) {
    // Guards the test above against a counter that never counts.
    allocations = 0;
    counting = true;
    auto *p = new std::vector<int>(100);
    counting = false;
    delete p;
    EXPECT_EQ(allocations.load(), 2u);
}

} // namespace
} // namespace edyn
