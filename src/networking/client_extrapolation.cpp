#include "body_def.hpp"
#include "client_context.hpp"
#include "edyn/dynamics/orientation.hpp"
#include "edyn/dynamics/position.hpp"
#include "edyn/dynamics/tags.hpp"
#include "edyn/dynamics/velocity.hpp"
#include "edyn/math/math.hpp"
#include "edyn/networking/networked_tag.hpp"
#include "edyn/shapes/paged_mesh_shape.hpp"
#include "edyn/simulation/discontinuity.hpp"
#include <algorithm>
#include <cmath>

// The client's extrapolations: started from the newest server motion, merged into the
// simulation when the client reaches their end time.

namespace edyn::client_detail {

// Corrections decay by decay_rate per step run since the last call.
void decay_discontinuities(registry &registry, client_context &ctx) {
    auto step = get_step_count(registry);
    auto steps = step - ctx.decay_step;
    ctx.decay_step = step;
    if (steps == 0) return;
    auto factor = std::pow(ctx.decay_rate, scalar(std::min<std::uint64_t>(steps, 1000)));
    for (auto [e, d] : registry.view<discontinuity>().each()) {
        d.position_offset = d.position_offset * factor;
        d.orientation_offset = slerp(quaternion_identity, d.orientation_offset, factor);
    }
}

namespace {
decoded_packet decode_local(const network_registry &types, std::vector<entity> entities,
                            const std::vector<packet::pool_snapshot> &pools, double time) {
    auto decoded = decode_pools(types, pools, entities.size());
    auto result = decoded_packet{time, std::move(entities), {}};
    if (decoded) result.pools = std::move(*decoded);
    return result;
}
} // namespace

void start_extrapolation(registry &registry, client_context &ctx, network_registry &types, double now) {
    auto input = std::make_unique<extrapolation_input>();
    input->settings = get_settings(registry);
    input->types.types = types.types;
    // The client's world as it is now, but for its own inputs: the recorded ones give their
    // state at the snapshot's time. Bodies go as definitions whose shapes share their immutable
    // geometry (triangle and convex meshes) rather than as bytes, from which every extrapolation
    // would rebuild each mesh: a terrain of 32,768 triangles cost 10 ms a snapshot. A paged
    // mesh, which loads pages as its world steps, is sent as bytes: the job gets its own.
    auto bodies = make_body_pool();
    auto writer = pool_writer(types, registry);
    auto position = std::uint32_t{0};
    for (auto e : registry.view<networked_tag>()) {
        writer.include(e);
        auto own = ctx.authored.contains(e);
        for (std::uint16_t i = 0; i < types.types.size(); ++i) {
            auto &t = types.types[i];
            if (i == network_index::motion || t.action || (t.input && own) || !t.has(registry, e)) continue;
            if (i == network_index::body && !registry.all_of<paged_mesh_shape>(e)) {
                bodies->positions.push_back(position);
                bodies->values.push_back(get_rigidbody_def(registry, e));
            } else {
                writer.add(e, i);
            }
        }
        ++position;
    }
    auto entities = std::vector<entity>{};
    auto pools = std::vector<packet::pool_snapshot>{};
    writer.finish(entities, pools);
    input->world = decode_local(types, std::move(entities), pools, now);
    // Bodies first, as in a received packet: constraints and components go on them.
    input->world.pools.insert(input->world.pools.begin(), std::move(bodies));
    // The server's state at the newest snapshot's time: the newest motion of every body.
    auto motion = make_motion_pool();
    input->snapshot.time = ctx.pending_time;
    for (auto &cached : ctx.motions) {
        if (cached.local == null || !registry.valid(cached.local)) continue;
        motion->positions.push_back(std::uint32_t(input->snapshot.entities.size()));
        motion->values.push_back(cached.motion);
        input->snapshot.entities.push_back(cached.local);
    }
    input->snapshot.pools.push_back(std::move(motion));
    ctx.has_pending = false;
    input->remote_to_local = ctx.remote_to_local;
    for (auto &entry : ctx.inputs)
        input->inputs.push_back(decode_local(types, to_local(ctx, entry.entities), entry.pools, entry.time));
    // Other clients' inputs, which the server forwarded with the snapshot: the client's own
    // entities are left out of them (the recorded inputs are the client's word on those).
    for (auto &entry : ctx.forwarded) {
        auto entities = to_local(ctx, entry.entities);
        for (auto &e : entities)
            if (ctx.authored.contains(e)) e = null;
        input->inputs.push_back(decode_local(types, std::move(entities), entry.pools, entry.time));
    }
    std::stable_sort(input->inputs.begin(), input->inputs.end(),
                     [](const decoded_packet &a, const decoded_packet &b) { return a.time < b.time; });
    input->start_time = input->snapshot.time;
    // The client steps while the job runs: it aims at the time the client will be at when it
    // merges the result.
    input->end_time = now + ctx.lead_steps * double(get_fixed_dt(registry));
    ctx.job_input = std::move(input);
    ctx.job->start([&ctx] {
        try {
            run_extrapolation(*ctx.job_input, ctx.job_result);
        } catch (...) {
            ctx.job_result.bodies.clear();
        }
    });
}

// Merges the finished extrapolation when the client is at its end time: the bodies take the
// extrapolated state, and the jump goes into their discontinuity. A result the client has not
// reached yet waits; one a step or two behind is carried forward ballistically; an older one
// is dropped (the next starts from a newer snapshot). Returns whether the job is free.
bool merge_extrapolation(registry &registry, client_context &ctx, double now) {
    auto dt = double(get_fixed_dt(registry));
    auto late = std::llround((now - ctx.job_result.end_time) / dt);
    if (late < 0) {
        if (late < -1) ctx.lead_steps = std::max(1, ctx.lead_steps - 1);
        return false;
    }
    if (late > 0) ctx.lead_steps = std::min(max_lead_steps, ctx.lead_steps + 1);
    if (late <= max_carried_steps) {
        auto &types = registry.ctx().get<network_registry>();
        auto muted = muted_scope(types);
        auto carry = scalar(double(late) * dt);
        for (auto &[e, m] : ctx.job_result.bodies) {
            if (!registry.valid(e) || !registry.all_of<rigidbody_tag>(e) || registry.all_of<static_tag>(e))
                continue;
            // A body at rest where the client has it already is left alone (not woken).
            if (m.linvel == vector3_zero && m.angvel == vector3_zero && registry.all_of<sleeping_tag>(e) &&
                distance_sqr(m.position, registry.get<position>(e)) < position_quantum * position_quantum &&
                std::abs(dot(m.orientation, registry.get<orientation>(e))) > scalar(0.99999))
                continue;
            auto new_pos = m.position + m.linvel * carry;
            auto new_orn = integrate(m.orientation, m.angvel, carry);
            auto &old_pos = registry.get<position>(e);
            auto &old_orn = registry.get<orientation>(e);
            auto &d = registry.get_or_emplace<discontinuity>(e);
            d.position_offset = d.position_offset + (old_pos - new_pos);
            d.orientation_offset = normalize(d.orientation_offset * old_orn * conjugate(new_orn));
            registry.replace<position>(e, new_pos);
            registry.replace<orientation>(e, new_orn);
            registry.replace<linvel>(e, m.linvel);
            registry.replace<angvel>(e, m.angvel);
        }
    }
    ctx.job_result.bodies.clear();
    ctx.job_input.reset();
    return true;
}

} // namespace edyn::client_detail
