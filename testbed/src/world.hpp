// Making a sample's world: a registry attached in an execution mode, the solver settings the
// panel changes, and the scene. The testbed and the screenshot check build worlds the same way,
// so that in sequential mode both reach the same transforms.
#ifndef EDYN_TESTBED_WORLD_HPP
#define EDYN_TESTBED_WORLD_HPP

#include "samples.hpp"
#include <edyn/edyn.hpp>
#include <memory>

namespace testbed {

struct world_settings {
    int substeps{6};
    int relax_iterations{1};
    int position_iterations{4};
    int restitution_iterations{8};
    float gravity_y{-9.8f};
    edyn::execution_mode mode{edyn::execution_mode::sequential};
};

// Sets the solver settings and gravity, and wakes every body so that they take effect.
void apply_settings(edyn::registry &registry, const world_settings &settings);

// A new registry, attached in settings.mode, with the settings applied and the sample built.
std::unique_ptr<edyn::registry> make_world(const sample &s, const world_settings &settings,
                                           sample_state &state);

} // namespace testbed

#endif // EDYN_TESTBED_WORLD_HPP
