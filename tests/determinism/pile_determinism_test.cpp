#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <edyn/edyn.hpp>
#include <edyn_scenes/scenes.hpp>
#include <fstream>
#include <gtest/gtest.h>
#include <iostream>
#include <map>
#include <sstream>
#include <string>

// Same inputs, same build → bitwise the same transforms. The pile scene runs 300 steps and every
// body's position, orientation and velocities are hashed (FNV-1a over their bytes, in the order
// the bodies were made).

namespace edyn {
namespace {

constexpr unsigned pile_bodies = 256;
constexpr int pile_steps = 300;

struct hasher {
    std::uint64_t value{14695981039346656037ull};
    void add(const void *data, std::size_t size) {
        auto *bytes = static_cast<const unsigned char *>(data);
        for (std::size_t i = 0; i < size; ++i) {
            value ^= bytes[i];
            value *= 1099511628211ull;
        }
    }
    void add(const vector3 &v) { add(&v, sizeof(v)); }
    void add(const quaternion &q) { add(&q, sizeof(q)); }
};

struct pile_run {
    registry reg;
    std::vector<entity> bodies;
    explicit pile_run(const init_config &config = init_config{execution_mode::sequential}) {
        attach(reg, config);
        scenes::make_ground(reg);
        bodies = scenes::make_pile(reg, pile_bodies, 8, 2, scenes::pile_shapes::with_polyhedra);
    }
    ~pile_run() { detach(reg); }

    std::uint64_t hash() const {
        hasher h;
        for (auto e : bodies) {
            h.add(reg.get<position>(e));
            h.add(reg.get<orientation>(e));
            h.add(reg.get<linvel>(e));
            h.add(reg.get<angvel>(e));
        }
        return h.value;
    }
};

std::uint64_t run_pile(const init_config &config = init_config{execution_mode::sequential}) {
    pile_run run(config);
    for (int i = 0; i < pile_steps; ++i)
        step_simulation(run.reg);
    // The asynchronous worker's steps reach this registry here; elsewhere it returns at once.
    wait_for_simulation(run.reg);
    return run.hash();
}

std::string hex(std::uint64_t v) {
    std::ostringstream s;
    s << std::hex << v;
    return s.str();
}

TEST(determinism, the_pile_gives_the_same_transforms_every_run) {
    auto first = run_pile();
    auto second = run_pile();
    EXPECT_EQ(hex(first), hex(second));
}

// The multithreaded step merges every parallel result in a fixed order: whatever the thread
// count, it gives the sequential step's transforms bit for bit.
TEST(determinism, the_multithreaded_step_gives_the_sequential_transforms) {
    auto sequential = run_pile();
    for (unsigned threads : {1u, 2u, 4u}) {
        init_config config;
        config.execution_mode = execution_mode::sequential_multithreaded;
        config.num_worker_threads = threads;
        config.min_parallel_bodies = 0; // below the default threshold: to the threads all the same
        EXPECT_EQ(hex(run_pile(config)), hex(sequential)) << threads << " threads";
    }
}

// The asynchronous worker receives the bodies in the order they were made and steps its own
// registry as the sequential mode steps the program's: the motion it sends back is the same, bit
// for bit.
TEST(determinism, the_asynchronous_worker_gives_the_sequential_transforms) {
    EXPECT_EQ(hex(run_pile(init_config{execution_mode::asynchronous})), hex(run_pile()));
}

// Joints too are solved colour by colour on the worker threads: a heap of rag dolls (hinges, CV
// joints and cones, all between moving bodies, landing on each other) gives the sequential
// step's transforms bit for bit.
std::uint64_t run_ragdolls(const init_config &config = init_config{execution_mode::sequential}) {
    registry reg;
    attach(reg, config);
    scenes::make_ground(reg);
    scenes::make_ragdoll_pile(reg, 32, 4);
    for (int i = 0; i < 150; ++i)
        step_simulation(reg);
    wait_for_simulation(reg);
    hasher h;
    for (auto e : reg.view<dynamic_tag>()) {
        h.add(reg.get<position>(e));
        h.add(reg.get<orientation>(e));
    }
    detach(reg);
    return h.value;
}

TEST(determinism, the_multithreaded_step_gives_the_sequential_rag_dolls) {
    auto sequential = run_ragdolls();
    EXPECT_EQ(hex(run_ragdolls(init_config{execution_mode::asynchronous})), hex(sequential))
        << "asynchronous";
    for (unsigned threads : {2u, 4u}) {
        init_config config;
        config.execution_mode = execution_mode::sequential_multithreaded;
        config.num_worker_threads = threads;
        config.min_parallel_bodies = 0; // below the default threshold: to the threads all the same
        EXPECT_EQ(hex(run_ragdolls(config)), hex(sequential)) << threads << " threads";
    }
}

// No state hidden outside the registry: two worlds stepped in turn match a world run alone.
TEST(determinism, interleaved_worlds_do_not_affect_each_other) {
    auto alone = run_pile();
    pile_run a, b;
    for (int i = 0; i < pile_steps; ++i) {
        step_simulation(a.reg);
        if (i % 3 != 0) step_simulation(b.reg);
    }
    EXPECT_EQ(hex(a.hash()), hex(alone));
    EXPECT_NE(hex(b.hash()), hex(alone)) << "b ran fewer steps, so it must differ: the hash sees motion";
}

// The hash pinned for this compiler and scalar type: one for every configuration the project
// supports (g++ 12 and clang 14, float and double; the sanitizer builds share their compiler's
// value, as sanitizers do not change floating-point results). A configuration with no value
// pinned fails, so that no build passes without being checked. A change to the physics changes
// the hashes: when the change is intended, rerun with EDYN_UPDATE_GOLDEN=1 in every
// configuration to record the new values.
std::string build_key() {
    std::ostringstream key;
#if defined(__clang__)
    key << "clang-" << __clang_major__;
#elif defined(__GNUC__)
    key << "gcc-" << __GNUC__;
#else
    key << "other";
#endif
    key << (sizeof(scalar) == 8 ? "-double" : "-float");
    return key.str();
}

TEST(determinism, the_pile_matches_its_pinned_hash) {
    const std::string path = EDYN_DETERMINISM_GOLDEN_FILE;
    std::map<std::string, std::string> golden;
    {
        std::ifstream in(path);
        std::string key, value;
        while (in >> key >> value)
            golden[key] = value;
    }
    auto key = build_key();
    auto measured = hex(run_pile());

    const char *update = std::getenv("EDYN_UPDATE_GOLDEN");
    if (update && std::strcmp(update, "1") == 0) {
        golden[key] = measured;
        std::ofstream out(path);
        for (auto &[k, v] : golden)
            out << k << ' ' << v << '\n';
        GTEST_SKIP() << "recorded " << key << ' ' << measured << " in " << path;
    }
    auto it = golden.find(key);
    ASSERT_NE(it, golden.end()) << "no hash pinned for " << key << " in " << path
                                << ": this configuration is unchecked. Run this test with "
                                   "EDYN_UPDATE_GOLDEN=1 to record "
                                << measured << " and commit the file";
    RecordProperty("configuration", key);
    std::cout << "determinism: checked the hash pinned for " << key << " (" << it->second << ")\n";
    EXPECT_EQ(measured, it->second) << "the pile's transforms after " << pile_steps << " steps changed for "
                                    << key
                                    << ". If the physics was changed on purpose, rerun this test with "
                                       "EDYN_UPDATE_GOLDEN=1 and commit "
                                    << path;
}

} // namespace
} // namespace edyn
