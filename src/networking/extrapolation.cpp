#include "extrapolation.hpp"
#include "edyn/dynamics/orientation.hpp"
#include "edyn/dynamics/position.hpp"
#include "edyn/dynamics/tags.hpp"
#include "edyn/dynamics/velocity.hpp"
#include "edyn/simulation/world.hpp"
#include "network_registry.hpp"
#include "step_time.hpp"
#include <algorithm>
#include <cmath>

namespace edyn {

namespace {

void apply(registry &registry, const network_registry &types, const decoded_packet &packet,
           const entity_map &to_job, const detail::entity_mapper &map) {
    auto entities = std::vector<entity>(packet.entities.size(), entity{null});
    for (std::size_t i = 0; i < entities.size(); ++i)
        if (packet.entities[i] != null) entities[i] = to_job.find(packet.entities[i]);
    apply_pools(registry, types, packet.pools, entities, map);
}

} // namespace

void run_extrapolation(const extrapolation_input &input, extrapolation_result &result) {
    result.end_time = input.start_time;
    result.bodies.clear();

    auto job = registry{};
    attach(job, init_config{execution_mode::sequential});
    set_fixed_dt(job, input.settings.fixed_dt);
    set_gravity(job, input.settings.gravity);
    set_solver_substeps(job, input.settings.num_substeps);
    set_solver_relax_iterations(job, input.settings.num_relax_iterations);
    set_solver_restitution_iterations(job, input.settings.num_restitution_iterations);
    set_solver_individual_restitution_iterations(job, input.settings.num_individual_restitution_iterations);
    set_pre_step_callback(job, input.settings.pre_step_callback);
    set_post_step_callback(job, input.settings.post_step_callback);

    // The client's entities → the job's.
    auto to_job = entity_map{};
    for (auto e : input.world.entities)
        to_job.insert(e, job.create());
    auto local_to_job = detail::entity_mapper([&](entity e) { return to_job.find(e); });
    auto remote_to_job =
        detail::entity_mapper([&](entity e) { return to_job.find(input.remote_to_local.find(e)); });

    auto dt = double(input.settings.fixed_dt);
    // An input is due by the step within half a step of its time, as on the server.
    auto next_input = std::size_t{0};
    auto due_by = [&](double step_time) {
        return next_input < input.inputs.size() &&
               detail::due_by_step(input.inputs[next_input].time, step_time, dt);
    };

    apply(job, input.types, input.world, to_job, local_to_job);
    while (due_by(input.start_time))
        apply(job, input.types, input.inputs[next_input++], to_job, remote_to_job);
    apply(job, input.types, input.snapshot, to_job, remote_to_job);

    // Capped in floating point before converting: times from the network may be far apart,
    // or not finite, and a double beyond the range of unsigned must never reach the conversion.
    auto due = std::round((input.end_time - input.start_time) / dt);
    auto steps = due > 0 ? unsigned(std::min(due, double(max_extrapolation_steps))) : 0u;
    for (unsigned k = 0; k < steps; ++k) {
        auto time = input.start_time + k * dt;
        while (due_by(time))
            apply(job, input.types, input.inputs[next_input++], to_job, remote_to_job);
        step_simulation(job);
    }
    result.end_time = input.start_time + steps * dt;

    for (auto local : input.snapshot.entities) {
        if (local == null) continue;
        auto e = to_job.find(local);
        if (e == null || !job.all_of<rigidbody_tag>(e) || job.all_of<static_tag>(e)) continue;
        result.bodies.emplace_back(local, network_motion{job.get<position>(e), job.get<orientation>(e),
                                                         job.get<linvel>(e), job.get<angvel>(e)});
    }
}

} // namespace edyn
