// The same small scene run in each execution mode: a stack of boxes, a ball rolling into it and
// a pendulum on a hinge. edyn promises the same transforms bit for bit in every mode, for any
// number of threads, given the same calls: this program checks that, and prints a hash of the
// final state that a reader can compare with the guide (it is the same on every run of one
// build; another compiler or scalar type gives another value).
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <edyn/edyn.hpp>
#include <vector>

namespace {

struct body_state {
    edyn::vector3 position, linvel, angvel;
    edyn::quaternion orientation;
};

std::vector<edyn::entity> make_scene(edyn::registry &registry) {
    auto ground_def = edyn::rigidbody_def();
    ground_def.kind = edyn::rigidbody_kind::rb_static;
    ground_def.shape = edyn::plane_shape{{0, 1, 0}, 0};
    edyn::make_rigidbody(registry, ground_def);

    std::vector<edyn::entity> bodies;
    auto def = edyn::rigidbody_def();
    def.mass = 1;
    def.shape = edyn::box_shape{0.25, 0.25, 0.25};
    for (int i = 0; i < 4; ++i) {
        def.position = {0, edyn::scalar(0.25 + 0.5 * i), 0};
        bodies.push_back(edyn::make_rigidbody(registry, def));
    }

    def.mass = 2;
    def.shape = edyn::sphere_shape{0.2};
    def.position = {-3, 0.2, 0};
    def.linvel = {4, 0, 0};
    bodies.push_back(edyn::make_rigidbody(registry, def));

    // A rod on a hinge about z, 2 m behind the stack, released from the horizontal.
    auto anchor_def = edyn::rigidbody_def();
    anchor_def.kind = edyn::rigidbody_kind::rb_static;
    anchor_def.position = {0, 3, -2};
    auto anchor = edyn::make_rigidbody(registry, anchor_def);
    auto rod_def = edyn::rigidbody_def();
    rod_def.mass = 1;
    rod_def.shape = edyn::box_shape{0.5, 0.05, 0.05};
    rod_def.position = {0.5, 3, -2};
    auto rod = edyn::make_rigidbody(registry, rod_def);
    edyn::make_constraint<edyn::hinge_constraint>(registry, anchor, rod, [](edyn::hinge_constraint &hinge) {
        hinge.pivot[0] = {0, 0, 0};
        hinge.pivot[1] = {-0.5, 0, 0};
        hinge.set_axes({0, 0, 1}, {0, 0, 1});
    });
    bodies.push_back(rod);
    return bodies;
}

// Runs 3 s of frames at 60 per second and returns every body's final state.
std::vector<body_state> run(const char *name, const edyn::init_config &config) {
    edyn::registry registry;
    edyn::attach(registry, config);
    auto bodies = make_scene(registry);
    for (int frame = 0; frame <= 180; ++frame) {
        edyn::update(registry, frame / 60.0);
        // Only the asynchronous mode has anything to wait for: there, update() sends the frame to
        // the worker and returns at once. Waiting makes each frame's steps complete before the
        // next, as they are in the other modes; a game would not wait.
        edyn::wait_for_simulation(registry);
    }
    std::vector<body_state> states;
    for (auto entity : bodies)
        states.push_back({registry.get<edyn::position>(entity), registry.get<edyn::linvel>(entity),
                          registry.get<edyn::angvel>(entity), registry.get<edyn::orientation>(entity)});
    auto top = registry.get<edyn::position>(bodies[3]);
    auto ball = registry.get<edyn::position>(bodies[4]);
    std::printf("%-30s %3d steps, top box at (%.3f, %.3f, %.3f) m, ball at x = %.3f m\n", name,
                int(edyn::get_step_count(registry)), top.x, top.y, top.z, ball.x);
    edyn::detach(registry);
    return states;
}

// A scheduler of the program's own, as a game engine with its own job system would give: this
// one runs every range of a task at once on the calling thread, the last range first, and tells
// edyn it has 8 threads, so that edyn splits its work 8 ways. The result must not change.
void *run_ranges_backwards(edyn::task_function fn, void *context, std::size_t count, std::size_t grain,
                           void *) {
    grain = std::max<std::size_t>(grain, 1);
    // The ranges [k grain, (k + 1) grain), the last one shorter, from the last to the first.
    for (auto end = count; end > 0;) {
        auto begin = (end - 1) / grain * grain;
        fn(context, begin, end);
        end = begin;
    }
    return nullptr;
}

void nothing_to_wait_for(void *, void *) {}

// FNV-1a over the bytes of every number, in the order the bodies were made.
std::uint64_t hash(const std::vector<body_state> &states) {
    std::uint64_t value = 14695981039346656037ull;
    auto add = [&](const edyn::scalar &number) {
        auto *bytes = reinterpret_cast<const unsigned char *>(&number);
        for (std::size_t i = 0; i < sizeof(number); ++i) {
            value ^= bytes[i];
            value *= 1099511628211ull;
        }
    };
    for (auto &state : states) {
        for (auto *v : {&state.position, &state.linvel, &state.angvel})
            for (int i = 0; i < 3; ++i)
                add((*v)[i]);
        add(state.orientation.x);
        add(state.orientation.y);
        add(state.orientation.z);
        add(state.orientation.w);
    }
    return value;
}

} // namespace

int main(int argc, char **) {
    if (argc > 1) {
        std::fprintf(stderr, "usage: edyn-example-execution_modes (it takes no arguments)\n");
        return 2;
    }

    auto sequential = run("sequential", {edyn::execution_mode::sequential});
    auto reference = hash(sequential);
    bool ok = true;
    auto check = [&](const char *name, const edyn::init_config &config) {
        auto same = hash(run(name, config)) == reference;
        ok = ok && same;
        if (!same) std::printf("  <-- %s differs from sequential\n", name);
    };
    auto multithreaded = edyn::init_config{edyn::execution_mode::sequential_multithreaded};
    multithreaded.num_worker_threads = 2;
    multithreaded.min_parallel_bodies = 0; // a small scene: on the threads all the same
    check("sequential_multithreaded", multithreaded);
    edyn::task_hooks hooks;
    hooks.enqueue = &run_ranges_backwards;
    hooks.wait = &nothing_to_wait_for;
    hooks.concurrency = 8;
    multithreaded.scheduler = hooks;
    check("  with the program's scheduler", multithreaded);
    check("asynchronous", {edyn::execution_mode::asynchronous});

    std::printf("hash of the final state: %016llx, %s\n", static_cast<unsigned long long>(reference),
                ok ? "the same bit for bit in every mode" : "NOT the same in every mode");
    return ok ? 0 : 1;
}
