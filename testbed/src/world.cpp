#include "world.hpp"

namespace testbed {

void apply_settings(edyn::registry &registry, const world_settings &settings) {
    edyn::set_solver_substeps(registry, unsigned(settings.substeps));
    edyn::set_solver_relax_iterations(registry, unsigned(settings.relax_iterations));
    edyn::set_solver_position_iterations(registry, unsigned(settings.position_iterations));
    edyn::set_solver_restitution_iterations(registry, unsigned(settings.restitution_iterations));
    edyn::set_gravity(registry, {0, edyn::scalar(settings.gravity_y), 0});
    // A sleeping pile would not notice the new gravity.
    for (auto e : registry.view<edyn::dynamic_tag>())
        edyn::wake_up_entity(registry, e);
}

std::unique_ptr<edyn::registry> make_world(const sample &s, const world_settings &settings,
                                           sample_state &state) {
    auto registry = std::make_unique<edyn::registry>();
    edyn::init_config config;
    config.execution_mode = settings.mode;
    edyn::attach(*registry, config);
    apply_settings(*registry, settings);
    state = s.build(*registry);
    return registry;
}

} // namespace testbed
