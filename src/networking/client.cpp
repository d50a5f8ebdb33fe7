#include "edyn/networking/client.hpp"
#include "client_context.hpp"
#include "edyn/dynamics/body_limits.hpp"
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
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

namespace edyn {

namespace client_detail {

void destroy_local(registry &registry, client_context &ctx, const std::vector<entity> &remote) {
    for (auto r : remote) {
        auto local = ctx.remote_to_local.find(r);
        if (local == null) continue;
        ctx.remote_to_local.erase(r);
        ctx.local_to_remote.erase(local);
        ctx.authored.erase(local);
        if (to_index(local) < ctx.motions.size() && ctx.motions[to_index(local)].local == local)
            ctx.motions[to_index(local)] = {};
        if (registry.valid(local)) {
            if (auto *asset = registry.try_get<client_asset>(local))
                for (auto &[index, member] : asset->members)
                    ctx.unlinked_members.erase(member);
            registry.destroy(local);
        }
    }
}

namespace {
// Whether `a` is a later version than `b` of the same index: versions wrap round, and the later
// is the one at most half their range ahead.
bool later_version(entity a, entity b) {
    auto ahead = (to_version(a) - to_version(b)) & entity_traits::version_mask;
    return ahead != 0 && ahead <= entity_traits::version_mask / 2;
}
} // namespace

bool make_room_for(registry &registry, client_context &ctx, entity remote) {
    auto mapped = ctx.remote_to_local.source_at(remote);
    if (mapped == null || mapped == remote) return true;
    if (!later_version(remote, mapped)) return false;
    destroy_local(registry, ctx, {mapped});
    return true;
}

} // namespace client_detail

using namespace client_detail;

namespace {

network_client_rejections &rejections(registry &registry) {
    return registry.ctx().get<network_client_rejections>();
}

// A time of the server's clock the client can compute with.
bool plausible_server_time(double t) { return std::abs(t) <= max_server_time; }

// Whether the value or removal of the type at `index` that a snapshot of `time` has for local
// entity `e` is not older than the one `e` has; then `time` becomes the one it has.
bool newer_value(client_context &ctx, std::uint16_t index, entity e, double time) {
    if (index >= ctx.value_times.size()) ctx.value_times.resize(std::size_t(index) + 1);
    auto &times = ctx.value_times[index];
    auto i = to_index(e);
    if (i >= times.size()) times.resize(std::size_t(i) + 1, {null, 0.0});
    auto &slot = times[i];
    if (slot.first == e && slot.second > time) return false;
    slot = {e, time};
    return true;
}

// Whether local entity `e` takes the value (or removal) of the type at `index` that a packet of
// `time` carries: not over the client's own inputs, nor over a value from a newer snapshot.
bool takes_value(const network_registry &types, client_context &ctx, std::uint16_t index, entity e,
                 double time) {
    return e != null && !(types.types[index].input && ctx.authored.contains(e)) &&
           newer_value(ctx, index, e, time);
}

void receive_create(registry &registry, client_context &ctx, const packet::create_entity &create) {
    auto &types = registry.ctx().get<network_registry>();
    auto pools = decode_pools(types, create.pools, create.entities.size());
    if (!pools) return;
    for (auto r : create.entities) {
        if (r == null || ctx.remote_to_local.find(r) != null || ctx.unlinked_members.contains(r)) continue;
        if (!make_room_for(registry, ctx, r)) continue;
        auto local = registry.create();
        registry.emplace<networked_tag>(local);
        ctx.remote_to_local.insert(r, local);
        ctx.local_to_remote.insert(local, r);
    }
    auto local = to_local(ctx, create.entities);
    auto muted = muted_scope(types);
    for (auto &pool : *pools) {
        // The program's values follow the rule of snapshots (a create_entity also updates
        // entities the client has, and may arrive after newer snapshots); edyn's own are whole
        // definitions, applied where they differ.
        auto index = pool->component_index;
        auto entities = local;
        if (index >= types.first_program_type) {
            for (auto position : pool->positions)
                if (!takes_value(types, ctx, index, local[position], create.timestamp))
                    entities[position] = null;
        }
        pool->apply(registry, entities, remote_to_local_map(ctx));
    }
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

// Whether every forwarded entry decodes to inputs only, at a time within the longest playout
// delay of the snapshot's (the server forwards what waits in its jitter buffers: inputs due
// within a playout delay, and late ones it has yet to apply).
enum class forwarded_check { ok, malformed, out_of_range };
forwarded_check check_forwarded(const network_registry &types, const packet::registry_snapshot &snapshot) {
    for (auto &entry : snapshot.inputs) {
        auto pools = decode_pools(types, entry.pools, entry.entities.size());
        if (!pools || !std::isfinite(entry.timestamp)) return forwarded_check::malformed;
        for (auto &pool : *pools)
            if (!types.types[pool->component_index].input) return forwarded_check::malformed;
        if (!(entry.timestamp >= snapshot.timestamp - max_playout_delay &&
              entry.timestamp <= snapshot.timestamp + max_playout_delay))
            return forwarded_check::out_of_range;
    }
    return forwarded_check::ok;
}

// The server forwards each of the other clients' inputs in two snapshots: the client keeps one
// copy of each, in time order, until a newer snapshot's motion holds its effect (it was applied
// before the step that snapshot follows). An input of the snapshot's own step may have been applied
// after the snapshot was made, so it stays for the extrapolation to apply at its start.
void keep_forwarded(registry &registry, client_context &ctx, const packet::registry_snapshot &snapshot) {
    using input = client_context::recorded_input;
    auto &kept = ctx.forwarded;
    for (auto &entry : snapshot.inputs) {
        auto same = [&](const input &k) { return k.time == entry.timestamp && k.entities == entry.entities; };
        if (std::any_of(kept.begin(), kept.end(), same)) continue;
        auto before = [](double t, const input &k) { return t < k.time; };
        auto at = std::upper_bound(kept.begin(), kept.end(), entry.timestamp, before);
        kept.insert(at, {entry.timestamp, entry.entities, entry.pools, 0});
    }
    auto applied_before = std::max(ctx.pending_time, snapshot.timestamp) - double(get_fixed_dt(registry)) / 2;
    auto applied = [&](const input &k) { return k.time < applied_before; };
    kept.erase(kept.begin(), std::partition_point(kept.begin(), kept.end(), applied));
    // Bounded against a server that forwards inputs far ahead of its snapshots: the oldest go.
    if (kept.size() > max_kept_forwarded)
        kept.erase(kept.begin(), kept.end() - std::ptrdiff_t(max_kept_forwarded));
}

// The removals of a snapshot, decoded: per pool, its network index and the positions of the
// entities that lost it. Empty when one names a type that is not the program's (or an action),
// or a position past the entities.
std::optional<std::vector<std::pair<std::uint16_t, std::vector<std::uint32_t>>>>
decode_removals(const network_registry &types, const packet::registry_snapshot &snapshot) {
    auto result = std::vector<std::pair<std::uint16_t, std::vector<std::uint32_t>>>{};
    for (auto &pool : snapshot.removed) {
        auto index = pool.component_index;
        if (index < types.first_program_type || index >= types.types.size() || types.types[index].action ||
            snapshot.entities.empty())
            return std::nullopt;
        auto &positions = result.emplace_back(index, std::vector<std::uint32_t>{}).second;
        auto archive = memory_input_archive(pool.data.data(), pool.data.size());
        while (archive.remaining() > 0) {
            auto position = archive.read_size(snapshot.entities.size() - 1);
            if (archive.failed() || positions.size() >= snapshot.entities.size()) return std::nullopt;
            positions.push_back(std::uint32_t(position));
        }
    }
    return result;
}

void receive_snapshot(registry &registry, client_context &ctx, const packet::registry_snapshot &snapshot) {
    auto &types = registry.ctx().get<network_registry>();
    auto pools = decode_pools(types, snapshot.pools, snapshot.entities.size());
    auto removals = decode_removals(types, snapshot);
    if (!pools || !removals || !std::isfinite(snapshot.timestamp)) return;
    auto forwarded = check_forwarded(types, snapshot);
    if (forwarded == forwarded_check::malformed) return;
    if (forwarded == forwarded_check::out_of_range || !plausible_server_time(snapshot.timestamp) ||
        (ctx.synchronised && snapshot.timestamp > client_time(registry, ctx) + max_snapshot_lead)) {
        rejections(registry).out_of_range += 1;
        return;
    }
    request_unknown(registry, ctx, snapshot.entities);
    auto local = to_local(ctx, snapshot.entities);

    // Components other than motion are applied now, and removals, unless the entity has a newer
    // value; the client's own inputs are its own.
    {
        auto muted = muted_scope(types);
        auto takes = [&](std::uint16_t index, entity e) {
            return takes_value(types, ctx, index, e, snapshot.timestamp);
        };
        for (auto &pool : *pools) {
            auto index = pool->component_index;
            if (index == network_index::motion) continue;
            auto entities = std::vector<entity>(local.size(), entity{null});
            for (auto position : pool->positions)
                if (takes(index, local[position])) entities[position] = local[position];
            pool->apply(registry, entities, remote_to_local_map(ctx));
        }
        for (auto &[index, positions] : *removals) {
            for (auto position : positions) {
                auto e = local[position];
                if (takes(index, e) && registry.valid(e)) types.types[index].remove(registry, e);
            }
        }
    }
    // Motion waits for the next extrapolation, body by body: the newest value of each.
    for (auto &pool : *pools) {
        if (pool->component_index != network_index::motion) continue;
        auto &values = static_cast<detail::typed_decoded_pool<network_motion> &>(*pool);
        for (std::size_t i = 0; i < values.positions.size(); ++i) {
            auto e = local[values.positions[i]];
            if (e == null) continue;
            auto index = to_index(e);
            if (index >= ctx.motions.size()) ctx.motions.resize(std::size_t(index) + 1);
            auto &cached = ctx.motions[index];
            if (cached.local == e && cached.time >= snapshot.timestamp) continue;
            cached = {e, snapshot.timestamp, values.values[i]};
        }
    }
    keep_forwarded(registry, ctx, snapshot);
    if (snapshot.timestamp > ctx.pending_time) {
        ctx.pending_time = snapshot.timestamp;
        ctx.has_pending = true;
    }
}

void receive_time(registry &registry, client_context &ctx, const packet::time_response &response) {
    auto &pending = ctx.pending_time_requests;
    auto request = std::find_if(pending.begin(), pending.end(), [&](auto &p) { return p.id == response.id; });
    if (request == pending.end() || !std::isfinite(response.timestamp)) return;
    if (!plausible_server_time(response.timestamp)) {
        rejections(registry).out_of_range += 1;
        return;
    }
    auto sent = request->sent;
    pending.erase(request);
    // The server's time was read somewhere between the request leaving and the reply arriving;
    // taken at the midpoint, a sample is off by half the difference of the two legs' delays,
    // which is at most half its round trip beyond the shortest. So of the samples the one with
    // the shortest round trip is the best (the minimum-delay filter of NTP): its legs were both
    // near the link's least delay, however the delays wander. Of samples with the same round trip
    // (times here are counted in steps) the first stays the best.
    auto local_now = get_simulation_time(registry);
    auto sample = client_context::clock_sample{response.timestamp - (sent + local_now) / 2, local_now - sent};
    auto &samples = ctx.offset_samples;
    if (samples.size() >= offset_samples_wanted) {
        // The offset is settled; a sample far from it is a new clock, which starts over.
        if (std::abs(sample.offset - ctx.clock_offset) <= 0.25) return;
        samples.clear();
    }
    samples.push_back(sample);
    ctx.clock_offset = std::min_element(samples.begin(), samples.end(), [](auto &a, auto &b) {
                           return a.round_trip < b.round_trip - 1e-9;
                       })->offset;
    ctx.synchronised = true;
}

// The server's settings, applied whole or, when one is out of range (validate_settings; a
// server's own settings never are), not at all.
void apply_server_settings(registry &registry, const packet::server_settings &s) {
    auto candidate = get_settings(registry);
    candidate.fixed_dt = s.fixed_dt;
    candidate.gravity = s.gravity;
    candidate.num_substeps = s.num_substeps;
    candidate.num_relax_iterations = s.num_relax_iterations;
    candidate.num_restitution_iterations = s.num_restitution_iterations;
    candidate.num_individual_restitution_iterations = s.num_individual_restitution_iterations;
    candidate.max_linear_speed = s.max_linear_speed;
    candidate.contact = s.contact;
    candidate.joint = s.joint;
    try {
        validate_settings(candidate, "client_receive_packet");
    } catch (const std::invalid_argument &) {
        rejections(registry).out_of_range += 1;
        return;
    }
    // Through the setter, which wakes resting bodies to the new gravity.
    set_gravity(registry, s.gravity);
    registry.ctx().get<settings>() = candidate;
}

// An entry is recorded when any of the client's inputs changed, and holds all of them: the
// entry at or before a time is the whole input state then, from which an extrapolation starts
// (an input set only after that time is absent from it, as it was on the server).
void record_inputs(registry &registry, client_context &ctx, network_registry &types, double now) {
    auto dt = double(get_fixed_dt(registry));
    auto owned_input = [&](std::size_t i, entity e) {
        return types.types[i].input && registry.valid(e) && ctx.local_to_remote.find(e) != null &&
               types.types[i].has(registry, e);
    };
    auto changed = false;
    for (auto i = types.first_program_type; i < types.types.size() && !changed; ++i)
        for (auto e : ctx.authored.entities())
            if (owned_input(i, e) && types.changed_at(i, e) >= ctx.last_input_record) changed = true;
    auto writer = pool_writer(types, registry, [&ctx](entity e) { return ctx.local_to_remote.find(e); });
    if (changed) {
        for (auto i = types.first_program_type; i < types.types.size(); ++i)
            for (auto e : ctx.authored.entities())
                if (owned_input(i, e)) writer.add(e, i);
    }
    ctx.last_input_record = types.now;
    if (!writer.empty()) {
        // Each entry a step after the last at least: the server keeps one input state a time,
        // and takes one stamped with a time it has, or one before what it applied, for a copy.
        // The client's time repeats steps when its lead moves down (a shorter round trip), and
        // a step when two updates run no step between them.
        auto time = ctx.inputs.empty() ? now : std::max(now, ctx.inputs.back().time + dt);
        auto entry = client_context::recorded_input{time, {}, {}, input_repeats};
        writer.finish(entry.entities, entry.pools);
        ctx.inputs.push_back(std::move(entry));
    }
    auto old = std::find_if(ctx.inputs.begin(), ctx.inputs.end(),
                            [&](auto &entry) { return entry.time >= now - history_length; });
    // The newest input older than the window is kept: it is the state the window starts from.
    if (old != ctx.inputs.begin()) --old;
    ctx.inputs.erase(ctx.inputs.begin(), old);
}

// Inputs go as they were recorded, each with its own time, by input_repeats consecutive
// updates, so that a lost packet loses none (the server ignores the copies).
void send_inputs(client_context &ctx) {
    for (auto &entry : ctx.inputs) {
        if (entry.sends_left <= 0) continue;
        --entry.sends_left;
        ctx.packet_signal.publish(
            {packet::registry_snapshot{entry.time, entry.entities, entry.pools, {}, {}}});
    }
}

// The actions of the last second, at the present time, at the snapshot rate.
void send_snapshot(registry &registry, client_context &ctx, network_registry &types, double now) {
    auto writer = pool_writer(types, registry, [&ctx](entity e) { return ctx.local_to_remote.find(e); });
    for (auto i = types.first_program_type; i < types.types.size(); ++i) {
        auto &t = types.types[i];
        if (!t.action) continue;
        for (auto e : ctx.authored.entities()) {
            if (!registry.valid(e) || ctx.local_to_remote.find(e) == null || !t.has(registry, e)) continue;
            writer.add(e, i);
        }
    }
    // Sent even when empty: its time tells the server how late the client's packets arrive
    // before there is any input to lose, so that the playout delay settles early.
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

} // namespace

void init_network_client(registry &registry) {
    if (!is_attached(registry))
        throw std::invalid_argument(
            "init_network_client: the registry is not attached (call edyn::attach first)");
    if (registry.ctx().contains<client_context>()) return;
    ensure_network_registry(registry);
    registry.ctx().emplace<network_client_rejections>();
    auto &ctx = registry.ctx().emplace<client_context>();
    ctx.job = std::make_unique<background_job>();
    ctx.decay_step = get_step_count(registry);
    // Just before a step (or, in asynchronous mode, an update) empties the action lists, their
    // actions go into the histories the snapshots carry.
    registry.ctx().emplace<detail::action_types>().before_clear = [](edyn::registry &r) {
        auto *client = r.ctx().find<client_context>();
        if (!client) return;
        auto now = client_time(r, *client);
        for (auto &t : r.ctx().get<network_registry>().types)
            if (t.record_actions) t.record_actions(r, now, history_length, double(get_fixed_dt(r)));
    };
}

void deinit_network_client(registry &registry) {
    auto *ctx = registry.ctx().find<client_context>();
    if (!ctx) return;
    ctx->job->wait();
    if (auto *actions = registry.ctx().find<detail::action_types>()) actions->before_clear = nullptr;
    registry.ctx().erase<client_context>();
    registry.ctx().erase<network_client_rejections>();
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
                if (p.value >= 0 && p.value <= max_playout_delay) {
                    ctx.playout_delay = p.value;
                } else {
                    rejections(registry).out_of_range += 1;
                }
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
    update_lead(registry, ctx);
    auto now = client_time(registry, ctx);
    types.now = now;

    decay_discontinuities(registry, ctx);

    // A request whose reply has not come within two round trips (a quarter second at least)
    // is taken as lost. Until the offset has its samples a request goes every update, then one
    // every time_request_interval.
    auto retry = std::max(2 * ctx.round_trip_time, 0.25);
    auto &pending = ctx.pending_time_requests;
    pending.erase(
        std::remove_if(pending.begin(), pending.end(), [&](auto &p) { return local_now >= p.sent + retry; }),
        pending.end());
    auto settling = ctx.offset_samples.size() < offset_samples_wanted;
    if (pending.size() < max_pending_time_requests && (settling || local_now >= ctx.next_time_request)) {
        auto id = ctx.next_request_id++;
        pending.push_back({id, local_now});
        ctx.next_time_request = local_now + time_request_interval;
        ctx.packet_signal.publish({packet::time_request{id}});
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

    if (ctx.synchronised) send_inputs(ctx);
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

const network_client_rejections &get_network_client_rejections(const registry &registry) {
    get_client(registry, "get_network_client_rejections");
    return registry.ctx().get<network_client_rejections>();
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

void wait_for_network_client(registry &registry) {
    get_client(registry, "wait_for_network_client").job->wait();
}

double get_network_client_time(const registry &registry) {
    auto &ctx = get_client(registry, "get_network_client_time");
    return client_time(registry, ctx);
}

} // namespace edyn
