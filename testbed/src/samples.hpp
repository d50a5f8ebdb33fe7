// The samples the testbed lists, by category: each builds one of the shared scenes (see
// scenes/) into a registry and says where the camera starts. The screenshot check builds them
// through the same list.
#ifndef EDYN_TESTBED_SAMPLES_HPP
#define EDYN_TESTBED_SAMPLES_HPP

#include "camera.hpp"
#include <edyn/edyn.hpp>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace testbed {

// What the keyboard asks of a sample each frame (the vehicle drives with it).
struct sample_input {
    float throttle{0}; // -1 to 1
    float steering{0}; // -1 to 1
};

// What a running sample keeps: a hook called before each frame's simulation update.
struct sample_state {
    std::function<void(edyn::registry &, const sample_input &, float dt)> on_frame;
    std::string help; // shown in the panel, e.g. the vehicle's keys
    // A body the camera's target follows (the vehicle), or null.
    edyn::entity follow{edyn::null};
};

struct sample {
    std::string name;
    std::string category;
    std::string description;
    orbit_camera camera;
    // Builds the scene into an attached registry (ground included where it has one).
    std::function<sample_state(edyn::registry &)> build;
};

const std::vector<sample> &all_samples();
const sample *find_sample(const std::string &name);
// "pyramid, tower, ..." for messages.
std::string sample_names();

// Runs `steps` fixed steps one by one, calling the sample's frame hook with no input before
// each and waiting for each step (asynchronous mode): how screenshots and their check advance a
// sample, identically in every execution mode.
// `after_step`, when given, gets each step's time in milliseconds.
void run_steps(edyn::registry &registry, sample_state &state, unsigned steps,
               const std::function<void(double)> &after_step = {});

// Marks a body to be drawn in a colour of its own instead of the palette (billiard balls).
struct body_tint {
    float r, g, b;
};
// Brightens a body for a moment (seconds left), e.g. on a contact event.
struct body_flash {
    float time_left{0};
};

} // namespace testbed

#endif // EDYN_TESTBED_SAMPLES_HPP
