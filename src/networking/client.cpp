#include "edyn/networking/client.hpp"
#include "edyn/dynamics/orientation.hpp"
#include "edyn/dynamics/position.hpp"
#include "edyn/dynamics/tags.hpp"
#include "edyn/dynamics/velocity.hpp"
#include "edyn/ecs/entity_map.hpp"
#include "edyn/math/math.hpp"
#include "edyn/networking/asset_ref.hpp"
#include "edyn/networking/networked_tag.hpp"
#include "edyn/parallel/background_job.hpp"
#include "edyn/simulation/discontinuity.hpp"
#include "edyn/simulation/world.hpp"
#include "entity_set.hpp"
#include "extrapolation.hpp"
#include "network_registry.hpp"
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace edyn {

namespace {

// A change is sent in this many consecutive snapshots, so that one lost packet loses nothing.
constexpr double change_repeats = 3;
// Actions and recorded inputs are kept this long (seconds of server time).
constexpr double history_length = 1;
constexpr double time_request_interval = 1;
// An entity a snapshot names before its create_entity arrived is asked for again after this.
constexpr double entity_request_interval = 0.5;
constexpr int max_lead_steps = 4;
// A result this many steps old is still carried forward; an older one is dropped.
constexpr long long max_carried_steps = 2;

struct client_context {
    network_client_packet_signal packet_signal;
    network_client_entity_signal entity_entered_signal;
    network_client_entity_signal instantiate_asset_signal;
    entity client_entity{null};
    entity_map remote_to_local, local_to_remote;
    entity_set authored; // local entities whose inputs this client set
    // Server entities of assets entered but not linked yet: instantiated by the program, never
    // asked for.
    entity_set unlinked_members;

    double round_trip_time{0};
    double snapshot_rate{30};
    scalar decay_rate{scalar(0.9)};
    double playout_delay{0};
    // Server time = local simulation time + clock_offset, once a time response arrived.
    bool synchronised{false};
    double clock_offset{0};
    std::uint32_t next_request_id{1};
    std::uint32_t pending_request_id{0};
    double time_request_sent{0};
    double next_time_request{-std::numeric_limits<double>::infinity()};
    double next_snapshot_time{-std::numeric_limits<double>::infinity()};

    // The newest server motion not yet extrapolated.
    bool has_pending{false};
    decoded_packet pending;
    std::vector<std::pair<entity, double>> requested; // remote entity, time asked

    // The client's inputs, oldest first, as the extrapolation re-applies them.
    struct recorded_input {
        double time;
        std::vector<entity> entities;
        std::vector<packet::pool_snapshot> pools;
    };
    std::vector<recorded_input> inputs;
    double last_input_record{-std::numeric_limits<double>::infinity()};

    std::uint64_t decay_step{0};
    bool actions_pending{false};
    std::uint64_t actions_step{0};

    // Steps ahead of the present an extrapolation aims at (adapted to how long jobs take).
    int lead_steps{1};
    std::unique_ptr<background_job> job;
    std::unique_ptr<extrapolation_input> job_input;
    extrapolation_result job_result;
};

// The client's record of an asset the server sent, on the local asset entity.
struct client_asset {
    entity remote{null};
    std::vector<std::pair<asset_index_type, entity>> members; // server entities
    bool linked{false};
    // The state the server sent for client_asset_ready, applied on linking.
    bool has_state{false};
    decoded_packet state;
};

client_context &get_client(registry &registry, const char *function) {
    auto *ctx = registry.ctx().find<client_context>();
    if (!ctx)
        throw std::invalid_argument(std::string(function) + ": the registry is not a network client "
                                                            "(call init_network_client first)");
    return *ctx;
}

const client_context &get_client(const registry &registry, const char *function) {
    return get_client(const_cast<edyn::registry &>(registry), function);
}

double client_time(const registry &registry, const client_context &ctx) {
    return get_simulation_time(registry) + ctx.clock_offset + ctx.playout_delay;
}

// Applies pools with the registry's change records muted: values from the server are not the
// client's changes.
struct muted_scope {
    network_registry &types;
    bool previous;
    explicit muted_scope(network_registry &t)
        : types(t)
        , previous(t.muted) {
        types.muted = true;
    }
    ~muted_scope() { types.muted = previous; }
};

std::vector<entity> to_local(const client_context &ctx, const std::vector<entity> &remote) {
    auto local = std::vector<entity>(remote.size(), entity{null});
    for (std::size_t i = 0; i < remote.size(); ++i)
        local[i] = ctx.remote_to_local.find(remote[i]);
    return local;
}

detail::entity_mapper remote_to_local_map(const client_context &ctx) {
    return [&ctx](entity e) { return ctx.remote_to_local.find(e); };
}

void destroy_local(registry &registry, client_context &ctx, const std::vector<entity> &remote) {
    for (auto r : remote) {
        auto local = ctx.remote_to_local.find(r);
        if (local == null) continue;
        ctx.remote_to_local.erase(r);
        ctx.local_to_remote.erase(local);
        ctx.authored.erase(local);
        if (registry.valid(local)) {
            if (auto *asset = registry.try_get<client_asset>(local))
                for (auto &[index, member] : asset->members)
                    ctx.unlinked_members.erase(member);
            registry.destroy(local);
        }
    }
}

void receive_create(registry &registry, client_context &ctx, const packet::create_entity &create) {
    auto &types = registry.ctx().get<network_registry>();
    auto pools = decode_pools(types, create.pools, create.entities.size());
    if (!pools) return;
    for (auto r : create.entities) {
        if (r == null || ctx.remote_to_local.find(r) != null || ctx.unlinked_members.contains(r)) continue;
        auto local = registry.create();
        registry.emplace<networked_tag>(local);
        ctx.remote_to_local.insert(r, local);
        ctx.local_to_remote.insert(local, r);
    }
    auto local = to_local(ctx, create.entities);
    auto muted = muted_scope(types);
    for (auto &pool : *pools)
        pool->apply(registry, local, remote_to_local_map(ctx));
}

void request_unknown(registry &registry, client_context &ctx, const std::vector<entity> &remote) {
    auto now = get_simulation_time(registry);
    auto request = packet::entity_request{};
    for (auto r : remote) {
        if (r == null || ctx.remote_to_local.find(r) != null || ctx.unlinked_members.contains(r)) continue;
        auto it =
            std::find_if(ctx.requested.begin(), ctx.requested.end(), [&](auto &p) { return p.first == r; });
        if (it != ctx.requested.end() && now - it->second < entity_request_interval) continue;
        if (it != ctx.requested.end()) {
            it->second = now;
        } else {
            ctx.requested.emplace_back(r, now);
        }
        request.entities.push_back(r);
    }
    if (!request.entities.empty()) ctx.packet_signal.publish({std::move(request)});
}

void carry_over_motion(const decoded_packet &older, decoded_packet &newer) {
    auto &from = static_cast<const detail::typed_decoded_pool<network_motion> &>(*older.pools.front());
    auto &to = static_cast<detail::typed_decoded_pool<network_motion> &>(*newer.pools.front());
    auto present = entity_set{};
    for (auto position : to.positions)
        if (newer.entities[position] != null) present.insert(newer.entities[position]);
    for (std::size_t i = 0; i < from.positions.size(); ++i) {
        auto e = older.entities[from.positions[i]];
        if (e == null || present.contains(e)) continue;
        to.positions.push_back(std::uint32_t(newer.entities.size()));
        newer.entities.push_back(e);
        to.values.push_back(from.values[i]);
    }
}

void receive_snapshot(registry &registry, client_context &ctx, const packet::registry_snapshot &snapshot) {
    auto &types = registry.ctx().get<network_registry>();
    auto pools = decode_pools(types, snapshot.pools, snapshot.entities.size());
    if (!pools || !std::isfinite(snapshot.timestamp)) return;
    request_unknown(registry, ctx, snapshot.entities);
    auto local = to_local(ctx, snapshot.entities);

    // Components other than motion are applied now; the client's own inputs are its own.
    {
        auto muted = muted_scope(types);
        for (auto &pool : *pools) {
            if (pool->component_index == network_index::motion) continue;
            auto entities = local;
            if (types.types[pool->component_index].input) {
                for (auto &e : entities)
                    if (ctx.authored.contains(e)) e = null;
            }
            pool->apply(registry, entities, remote_to_local_map(ctx));
        }
    }
    // Motion waits for the next extrapolation; a newer snapshot replaces an older one, except for
    // the bodies only the older one has (those that fell asleep in between: their resting pose
    // is not repeated).
    if (ctx.has_pending && ctx.pending.time >= snapshot.timestamp) return;
    auto pending = decoded_packet{snapshot.timestamp, local, {}};
    for (auto &pool : *pools)
        if (pool->component_index == network_index::motion) pending.pools.push_back(std::move(pool));
    if (pending.pools.empty()) {
        pending.pools.push_back(std::make_unique<detail::typed_decoded_pool<network_motion>>());
        pending.pools.back()->component_index = network_index::motion;
    }
    if (ctx.has_pending) carry_over_motion(ctx.pending, pending);
    ctx.pending = std::move(pending);
    ctx.has_pending = true;
}

void receive_entered(registry &registry, client_context &ctx, const packet::entity_entered &entered) {
    for (auto &asset : entered.assets) {
        if (asset.asset_entity == null || ctx.remote_to_local.find(asset.asset_entity) != null) continue;
        auto local = registry.create();
        registry.emplace<asset_ref>(local, asset_ref{asset.id, {}});
        registry.emplace<client_asset>(local,
                                       client_asset{asset.asset_entity, asset.members, false, false, {}});
        ctx.remote_to_local.insert(asset.asset_entity, local);
        ctx.local_to_remote.insert(local, asset.asset_entity);
        for (auto &[index, remote] : asset.members)
            ctx.unlinked_members.insert(remote);
        ctx.entity_entered_signal.publish(local);
    }
}

void receive_asset_state(registry &registry, client_context &ctx,
                         const packet::asset_sync_response &response) {
    auto local = ctx.remote_to_local.find(response.asset_entity);
    if (local == null || !registry.valid(local) || !registry.all_of<client_asset>(local)) return;
    auto &types = registry.ctx().get<network_registry>();
    auto pools = decode_pools(types, response.pools, response.entities.size());
    if (!pools) return;
    auto &asset = registry.get<client_asset>(local);
    asset.state = decoded_packet{response.timestamp, response.entities, std::move(*pools)};
    asset.has_state = true;
    ctx.instantiate_asset_signal.publish(local);
}

void receive_time(registry &registry, client_context &ctx, const packet::time_response &response) {
    if (response.id != ctx.pending_request_id || !std::isfinite(response.timestamp)) return;
    ctx.pending_request_id = 0;
    // The reply left the server half a round trip ago.
    auto offset = response.timestamp + ctx.round_trip_time / 2 - get_simulation_time(registry);
    if (!ctx.synchronised || std::abs(offset - ctx.clock_offset) > 0.25) {
        ctx.clock_offset = offset;
    } else {
        ctx.clock_offset += (offset - ctx.clock_offset) * 0.2;
    }
    ctx.synchronised = true;
}

void apply_server_settings(registry &registry, const packet::server_settings &s) {
    if (!(s.fixed_dt > 0) || !std::isfinite(s.fixed_dt)) return;
    set_fixed_dt(registry, s.fixed_dt);
    if (std::isfinite(s.gravity.x) && std::isfinite(s.gravity.y) && std::isfinite(s.gravity.z))
        set_gravity(registry, s.gravity);
    if (s.num_substeps > 0) set_solver_substeps(registry, s.num_substeps);
    set_solver_relax_iterations(registry, s.num_relax_iterations);
    set_solver_restitution_iterations(registry, s.num_restitution_iterations);
    set_solver_individual_restitution_iterations(registry, s.num_individual_restitution_iterations);
}

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

void record_inputs(registry &registry, client_context &ctx, network_registry &types, double now) {
    auto writer = pool_writer(types, registry);
    for (auto i = types.first_program_type; i < types.types.size(); ++i) {
        auto &t = types.types[i];
        if (!t.input) continue;
        for (auto e : ctx.authored.entities()) {
            if (registry.valid(e) && t.has(registry, e) && types.changed_at(i, e) > ctx.last_input_record)
                writer.add(e, i);
        }
    }
    ctx.last_input_record = types.now;
    if (!writer.empty()) {
        auto entry = client_context::recorded_input{now, {}, {}};
        writer.finish(entry.entities, entry.pools);
        ctx.inputs.push_back(std::move(entry));
    }
    auto old = std::find_if(ctx.inputs.begin(), ctx.inputs.end(),
                            [&](auto &entry) { return entry.time >= now - history_length; });
    // The newest input older than the window is kept: it is the state the window starts from.
    if (old != ctx.inputs.begin()) --old;
    ctx.inputs.erase(ctx.inputs.begin(), old);
}

void send_snapshot(registry &registry, client_context &ctx, network_registry &types, double now) {
    auto since = now - change_repeats / std::max(ctx.snapshot_rate, 1e-3);
    auto writer = pool_writer(types, registry, [&ctx](entity e) { return ctx.local_to_remote.find(e); });
    for (auto i = types.first_program_type; i < types.types.size(); ++i) {
        auto &t = types.types[i];
        if (!t.input && !t.action) continue;
        for (auto e : ctx.authored.entities()) {
            if (!registry.valid(e) || ctx.local_to_remote.find(e) == null || !t.has(registry, e)) continue;
            if (t.action || types.changed_at(i, e) >= since) writer.add(e, i);
        }
    }
    if (writer.empty()) return;
    auto snapshot = packet::registry_snapshot{};
    snapshot.timestamp = now;
    writer.finish(snapshot.entities, snapshot.pools);
    ctx.packet_signal.publish({std::move(snapshot)});
}

// Entities whose inputs or actions the program set are the client's own.
void note_authored(registry &registry, client_context &ctx, network_registry &types) {
    for (auto i = types.first_program_type; i < types.types.size(); ++i) {
        auto &t = types.types[i];
        if (!t.input && !t.action) continue;
        // Actions: any entity with an action list; inputs: changed by the program.
        auto &changes = types.changes[i];
        if (t.input) {
            for (auto &c : changes)
                if (c.e != null && registry.valid(c.e) && ctx.local_to_remote.find(c.e) != null)
                    ctx.authored.insert(c.e);
        }
    }
}

decoded_packet decode_local(const network_registry &types, std::vector<entity> entities,
                            const std::vector<packet::pool_snapshot> &pools, double time) {
    auto decoded = decode_pools(types, pools, entities.size());
    auto result = decoded_packet{time, std::move(entities), {}};
    if (decoded) result.pools = std::move(*decoded);
    return result;
}

void start_extrapolation(registry &registry, client_context &ctx, network_registry &types, double now) {
    auto input = std::make_unique<extrapolation_input>();
    input->settings = get_settings(registry);
    input->types.types = types.types;
    // The client's world as it is now.
    auto writer = pool_writer(types, registry);
    for (auto e : registry.view<networked_tag>()) {
        writer.include(e);
        for (std::uint16_t i = 0; i < types.types.size(); ++i) {
            auto &t = types.types[i];
            if (i == network_index::motion || t.action) continue;
            if (t.has(registry, e)) writer.add(e, i);
        }
    }
    auto entities = std::vector<entity>{};
    auto pools = std::vector<packet::pool_snapshot>{};
    writer.finish(entities, pools);
    input->world = decode_local(types, std::move(entities), pools, now);
    input->snapshot = std::move(ctx.pending);
    ctx.has_pending = false;
    input->remote_to_local = ctx.remote_to_local;
    for (auto &entry : ctx.inputs)
        input->inputs.push_back(decode_local(types, entry.entities, entry.pools, entry.time));
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

} // namespace

void init_network_client(registry &registry) {
    if (!is_attached(registry))
        throw std::invalid_argument(
            "init_network_client: the registry is not attached (call edyn::attach first)");
    if (registry.ctx().contains<client_context>()) return;
    ensure_network_registry(registry);
    auto &ctx = registry.ctx().emplace<client_context>();
    ctx.job = std::make_unique<background_job>();
    ctx.decay_step = get_step_count(registry);
}

void deinit_network_client(registry &registry) {
    auto *ctx = registry.ctx().find<client_context>();
    if (!ctx) return;
    ctx->job->wait();
    registry.ctx().erase<client_context>();
}

sink<network_client_packet_signal> network_client_packet_sink(registry &registry) {
    return sink{get_client(registry, "network_client_packet_sink").packet_signal};
}

void client_receive_packet(registry &registry, const packet::edyn_packet &packet) {
    auto &ctx = get_client(registry, "client_receive_packet");
    std::visit(
        [&](const auto &p) {
            using T = std::decay_t<decltype(p)>;
            if constexpr (std::is_same_v<T, packet::registry_snapshot>) {
                receive_snapshot(registry, ctx, p);
            } else if constexpr (std::is_same_v<T, packet::create_entity>) {
                receive_create(registry, ctx, p);
            } else if constexpr (std::is_same_v<T, packet::destroy_entity>) {
                destroy_local(registry, ctx, p.entities);
            } else if constexpr (std::is_same_v<T, packet::entity_exited>) {
                destroy_local(registry, ctx, p.entities);
            } else if constexpr (std::is_same_v<T, packet::entity_entered>) {
                receive_entered(registry, ctx, p);
            } else if constexpr (std::is_same_v<T, packet::asset_sync_response>) {
                receive_asset_state(registry, ctx, p);
            } else if constexpr (std::is_same_v<T, packet::time_response>) {
                receive_time(registry, ctx, p);
            } else if constexpr (std::is_same_v<T, packet::set_playout_delay>) {
                if (std::isfinite(p.value) && p.value >= 0) ctx.playout_delay = p.value;
            } else if constexpr (std::is_same_v<T, packet::server_settings>) {
                apply_server_settings(registry, p);
            } else if constexpr (std::is_same_v<T, packet::client_created>) {
                ctx.client_entity = p.client_entity;
            }
        },
        packet.var);
}

void update_network_client(registry &registry) {
    auto &ctx = get_client(registry, "update_network_client");
    auto &types = registry.ctx().get<network_registry>();
    auto local_now = get_simulation_time(registry);
    auto now = client_time(registry, ctx);
    types.now = now;

    decay_discontinuities(registry, ctx);

    // A request whose reply has not come within two round trips (a quarter second at least)
    // is taken as lost and made again.
    auto retry = std::max(2 * ctx.round_trip_time, 0.25);
    if (ctx.pending_request_id != 0 && local_now >= ctx.time_request_sent + retry) ctx.pending_request_id = 0;
    if (ctx.pending_request_id == 0 && (local_now >= ctx.next_time_request || !ctx.synchronised)) {
        ctx.pending_request_id = ctx.next_request_id++;
        ctx.time_request_sent = local_now;
        ctx.next_time_request = local_now + time_request_interval;
        ctx.packet_signal.publish({packet::time_request{ctx.pending_request_id}});
    }

    // Actions recorded last time were consumed by the steps run since.
    if (ctx.actions_pending && get_step_count(registry) > ctx.actions_step) {
        for (auto &t : types.types)
            if (t.clear_actions) t.clear_actions(registry, true);
        ctx.actions_pending = false;
    }
    for (auto &t : types.types) {
        if (!t.record_actions) continue;
        t.record_actions(registry, now, history_length);
        ctx.actions_pending = true;
        ctx.actions_step = get_step_count(registry);
    }
    for (auto i = types.first_program_type; i < types.types.size(); ++i) {
        if (!types.types[i].action) continue;
        for (auto e : registry.view<networked_tag>())
            if (types.types[i].has(registry, e)) ctx.authored.insert(e);
    }
    note_authored(registry, ctx, types);
    record_inputs(registry, ctx, types, now);

    if (ctx.job_input && ctx.job->finished()) merge_extrapolation(registry, ctx, now);
    if (ctx.synchronised && ctx.has_pending && !ctx.job_input) start_extrapolation(registry, ctx, types, now);

    if (ctx.synchronised && local_now >= ctx.next_snapshot_time) {
        ctx.next_snapshot_time = local_now + 1 / std::max(ctx.snapshot_rate, 1e-3) - 1e-9;
        send_snapshot(registry, ctx, types, now);
    }
}

void set_network_client_round_trip_time(registry &registry, double rtt) {
    auto &ctx = get_client(registry, "set_network_client_round_trip_time");
    if (!(rtt >= 0) || !std::isfinite(rtt))
        throw std::invalid_argument("set_network_client_round_trip_time: rtt must be finite and >= 0, got " +
                                    std::to_string(rtt));
    ctx.round_trip_time = rtt;
}

void set_network_client_snapshot_rate(registry &registry, double rate) {
    auto &ctx = get_client(registry, "set_network_client_snapshot_rate");
    if (!(rate > 0) || !std::isfinite(rate))
        throw std::invalid_argument("set_network_client_snapshot_rate: rate must be finite and > 0, got " +
                                    std::to_string(rate));
    ctx.snapshot_rate = rate;
}

void set_network_client_discontinuity_decay_rate(registry &registry, scalar rate) {
    auto &ctx = get_client(registry, "set_network_client_discontinuity_decay_rate");
    if (!(rate >= 0 && rate < 1))
        throw std::invalid_argument(
            "set_network_client_discontinuity_decay_rate: rate must be in [0, 1), got " +
            std::to_string(rate));
    ctx.decay_rate = rate;
}

entity get_network_client_entity(const registry &registry) {
    return get_client(registry, "get_network_client_entity").client_entity;
}

entity client_local_entity(const registry &registry, entity remote) {
    return get_client(registry, "client_local_entity").remote_to_local.find(remote);
}

entity client_remote_entity(const registry &registry, entity local) {
    return get_client(registry, "client_remote_entity").local_to_remote.find(local);
}

sink<network_client_entity_signal> network_client_entity_entered_sink(registry &registry) {
    return sink{get_client(registry, "network_client_entity_entered_sink").entity_entered_signal};
}

sink<network_client_entity_signal> network_client_instantiate_asset_sink(registry &registry) {
    return sink{get_client(registry, "network_client_instantiate_asset_sink").instantiate_asset_signal};
}

namespace {
client_asset &get_client_asset(registry &registry, entity asset_entity, const char *function) {
    if (!registry.valid(asset_entity) || !registry.all_of<client_asset, asset_ref>(asset_entity))
        throw std::invalid_argument(std::string(function) + ": entity " +
                                    std::to_string(to_index(asset_entity)) +
                                    " is not an asset the server sent");
    return registry.get<client_asset>(asset_entity);
}
} // namespace

void client_link_asset(registry &registry, entity asset_entity) {
    auto &ctx = get_client(registry, "client_link_asset");
    auto &asset = get_client_asset(registry, asset_entity, "client_link_asset");
    auto &ref = registry.get<asset_ref>(asset_entity);
    for (auto &[index, remote] : asset.members) {
        auto it = ref.entities.find(index);
        ctx.unlinked_members.erase(remote);
        if (it == ref.entities.end() || !registry.valid(it->second)) continue;
        auto local = it->second;
        if (auto previous = ctx.local_to_remote.find(local); previous != null)
            ctx.remote_to_local.erase(previous);
        ctx.remote_to_local.insert(remote, local);
        ctx.local_to_remote.insert(local, remote);
        registry.emplace_or_replace<networked_tag>(local);
    }
    asset.linked = true;
    if (asset.has_state) {
        auto &types = registry.ctx().get<network_registry>();
        auto muted = muted_scope(types);
        apply_pools(registry, types, asset.state.pools, to_local(ctx, asset.state.entities),
                    remote_to_local_map(ctx));
        asset.has_state = false;
        asset.state = {};
    }
}

void client_asset_ready(registry &registry, entity asset_entity) {
    auto &ctx = get_client(registry, "client_asset_ready");
    auto &asset = get_client_asset(registry, asset_entity, "client_asset_ready");
    ctx.packet_signal.publish({packet::asset_sync{asset.remote}});
}

void wait_for_network_client(registry &registry) {
    get_client(registry, "wait_for_network_client").job->wait();
}

double get_network_client_time(const registry &registry) {
    auto &ctx = get_client(registry, "get_network_client_time");
    return client_time(registry, ctx);
}

} // namespace edyn
