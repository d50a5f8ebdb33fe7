#include "edyn/networking/server.hpp"
#include "edyn/dynamics/orientation.hpp"
#include "edyn/dynamics/position.hpp"
#include "edyn/dynamics/tags.hpp"
#include "edyn/dynamics/velocity.hpp"
#include "edyn/networking/asset_ref.hpp"
#include "edyn/simulation/world.hpp"
#include "entity_set.hpp"
#include "interest.hpp"
#include "network_registry.hpp"
#include "step_time.hpp"
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace edyn {

using detail::add_assets;
using detail::add_with_island;
using detail::collect_interest;
using detail::gather_interest_boxes;
using detail::recentre_on_owned;

namespace {

// A change is sent in this many consecutive snapshots, so that one lost packet loses nothing.
constexpr double change_repeats = 3;
// An awake body whose motion has not changed is sent in one snapshot of this many.
constexpr std::uint8_t rest_refresh = 4;
// A client's jitter buffer holds at most this many snapshots; a client sending faster than the
// server applies loses its oldest ones.
constexpr std::size_t max_buffered_snapshots = 128;
// Most inputs of other clients one snapshot forwards (a client's jitter buffer holds a playout
// delay's worth of its inputs, one per step at most).
constexpr std::size_t max_forwarded_inputs = 256;
// A client's input goes to each other client in the first this many snapshots sent to it after
// the input arrived (rather than in every one while it waits), so that one lost packet loses
// none of them: the clients keep the inputs they were forwarded until the server applies them.
constexpr std::size_t forward_repeats = 2;
// A create_entity packet is cut before its values reach this many bytes (unless it holds one
// entity): a client decodes at most max_archive_count bytes in a pool, and transports carry
// smaller packets more easily.
constexpr std::size_t max_create_bytes = std::size_t{256} * 1024;
// Most entities one entity_request may ask for.
constexpr std::size_t max_requested_entities = 1024;
// Lost packets in a row that an input survives: its copies go a frame apart, and the playout
// delay leaves its first packet as many steps to spare (at 10 % loss an input is then missed
// once in ten thousand). More cover makes the delay longer, and with it how far the clients
// extrapolate.
constexpr int input_loss_cover = 3;
static_assert(input_loss_cover < input_repeats);
// The playout margin starts at this many steps and grows to this many at most. It starts above
// the slack an input's copies need (input_loss_cover - 1/2 steps) by enough that the tail of the
// link's delays, which the first second's packets do not all show, seldom makes it grow later:
// each growth moves the client's lead up, and the steps its time skips then hold the inputs
// before them. Over 27 runs of a 100 ms (± 20 ms) link at 10 % loss, starting at 2 steps let 8
// driven paths stray from the clean link's (a skipped step, amplified by collisions), at 4 none
// (edyn-netbench --scenario convergence); the clients' view error fell a little with it.
constexpr double initial_playout_margin_steps = 4;
constexpr double max_playout_margin_steps = 10;

struct buffered_snapshot {
    double timestamp;
    std::vector<entity> entities;
    std::vector<std::unique_ptr<detail::decoded_pool>> pools;
    // Its input pools as they came, forwarded to the other clients.
    std::vector<packet::pool_snapshot> input_pools;
    // server_context::sequence when it arrived.
    std::uint64_t arrival{0};
    // Whether it carries inputs (state, applied in time order) or only actions (each entry
    // applied once whenever it comes) and nothing else.
    bool has_inputs() const noexcept { return !input_pools.empty(); }
};

// The server's record of a client, on its entity next to remote_client.
struct server_client_state {
    entity_set known;
    std::vector<buffered_snapshot> jitter_buffer; // by timestamp
    double last_applied{-std::numeric_limits<double>::infinity()};
    // The newest time of a snapshot received from the client.
    double newest_received{-std::numeric_limits<double>::infinity()};
    double next_snapshot_time{0};
    // Added to half the round trip to make the playout delay; grows when snapshots arrive late.
    double playout_margin{-1};
    // A growth of the margin reaches the client's packets about a round trip later: until then,
    // packets it sent before it heard of it are as late as the one that made it grow, and may
    // make it grow only to what they need beyond the margin they were sent with.
    double margin_before_growth{0};
    double growth_settles{-std::numeric_limits<double>::infinity()};
    // What the newest snapshot before the last one lacked of the slack wanted (0 if nothing): a
    // packet held up on its way alone is covered by the copies after it, so the margin grows only
    // when two newest ones in a row come short, by the lesser lack.
    double last_lack{0};
    double playout_sent{-1};
    // The encoding of each known body's motion last sent to the client (a hash of it), and how
    // many more snapshots repeat it, by entity index.
    struct sent_motion {
        entity e{null};
        std::uint64_t hash{0};
        std::uint8_t repeats{0};
        std::uint8_t skipped{0};
    };
    std::vector<sent_motion> sent;
    // server_context::sequence at the last forward_repeats snapshots sent to the client, oldest
    // first: an input that arrived after the oldest of them has not been forwarded that often.
    std::array<std::uint64_t, forward_repeats> recent_sends{};
    // Whether the client was told who it is and the settings (at the first update after
    // server_make_client, so that the program knows the client's entity when its packets go).
    bool greeted{false};
};

struct server_context {
    network_server_packet_signal packet_signal;
    std::vector<entity> destroyed;
    packet::server_settings settings_sent{};
    // The networked entities' boxes for the AABBs of interest, made once per update (when a
    // client needs them) and kept to reuse their memory.
    std::vector<std::pair<entity, AABB>> interest_boxes;
    bool boxes_ready{false};
    // Counts the clients' inputs received and the snapshots sent, in the order they happen.
    std::uint64_t sequence{0};
    // The bodies and constraints the program changed since the last update, each once, in the
    // order of their first change; kept to reuse its memory.
    entity_set redefined;
};

server_context &get_server(registry &registry, const char *function) {
    auto *ctx = registry.ctx().find<server_context>();
    if (!ctx)
        throw std::invalid_argument(std::string(function) + ": the registry is not a network server "
                                                            "(call init_network_server first)");
    return *ctx;
}

bool valid_snapshot_rate(double rate) noexcept { return rate > 0 && std::isfinite(rate); }

remote_client &get_client(registry &registry, entity client, const char *function) {
    auto *rc = registry.valid(client) ? registry.try_get<remote_client>(client) : nullptr;
    if (!rc || !registry.all_of<server_client_state>(client))
        throw std::invalid_argument(std::string(function) + ": entity " + std::to_string(to_index(client)) +
                                    " is not a client made by server_make_client");
    return *rc;
}

void send(registry &registry, server_context &ctx, entity client, packet::edyn_packet packet) {
    registry.get<remote_client>(client).packets_sent += 1;
    ctx.packet_signal.publish(client, packet);
}

void on_networked_destroyed(registry &registry, entity e) {
    if (auto *ctx = registry.ctx().find<server_context>()) ctx->destroyed.push_back(e);
}

packet::server_settings current_settings(const registry &registry) {
    auto &s = get_settings(registry);
    return {s.fixed_dt,
            s.gravity,
            s.num_substeps,
            s.num_relax_iterations,
            s.num_restitution_iterations,
            s.num_individual_restitution_iterations,
            s.max_linear_speed,
            s.contact,
            s.joint};
}

bool owns(const remote_client &rc, entity e) {
    return std::find(rc.owned_entities.begin(), rc.owned_entities.end(), e) != rc.owned_entities.end();
}

packet::entered_asset describe_asset(const registry &registry, entity asset) {
    auto &ref = registry.get<asset_ref>(asset);
    auto entered = packet::entered_asset{asset, ref.id, {}};
    for (auto &[index, e] : ref.entities)
        entered.members.emplace_back(index, e);
    return entered;
}

// Adds `e` and every networked value of its but motion (which snapshots carry).
void add_whole(const registry &registry, const network_registry &types, pool_writer &writer, entity e) {
    writer.include(e);
    for (std::uint16_t i = 0; i < types.types.size(); ++i) {
        auto &t = types.types[i];
        if (i == network_index::motion || t.action) continue;
        if (t.has(registry, e)) writer.add(e, i);
    }
}

// Sends the entities in create_entity packets of at most about max_create_bytes each, so that no
// pool exceeds what a client decodes (max_archive_count bytes). An entity too large for one
// alone is left out and counted.
void send_create(registry &registry, server_context &ctx, const network_registry &types, entity client,
                 const std::vector<entity> &entities) {
    auto writer = pool_writer(types, registry);
    auto flush = [&] {
        if (writer.empty()) return;
        auto create = packet::create_entity{};
        create.timestamp = get_simulation_time(registry);
        writer.finish(create.entities, create.pools);
        send(registry, ctx, client, {std::move(create)});
    };
    auto alone = pool_writer(types, registry);
    for (auto e : entities) {
        alone.clear();
        add_whole(registry, types, alone, e);
        auto size = alone.bytes();
        if (alone.largest_pool() > max_archive_count) {
            registry.get<remote_client>(client).entities_too_large += 1;
            continue;
        }
        if (!writer.empty() && writer.bytes() + size > max_create_bytes) flush();
        add_whole(registry, types, writer, e);
    }
    flush();
}

void update_interest(registry &registry, server_context &ctx, const network_registry &types, entity client,
                     remote_client &rc, server_client_state &state) {
    recentre_on_owned(registry, rc);
    // Made by the first client whose interest is updated in this update_network_server.
    if (!ctx.boxes_ready) {
        gather_interest_boxes(registry, ctx.interest_boxes);
        ctx.boxes_ready = true;
    }
    auto interest = entity_set{};
    collect_interest(registry, ctx.interest_boxes, rc.aabb_of_interest, interest);
    // Owned entities are always the client's, wherever they are.
    for (auto e : rc.owned_entities)
        if (registry.valid(e) && registry.all_of<networked_tag>(e)) add_with_island(registry, e, interest);
    add_assets(registry, interest);

    auto exited = packet::entity_exited{};
    for (auto e : state.known.entities())
        if (!interest.contains(e)) exited.entities.push_back(e);
    for (auto e : exited.entities)
        state.known.erase(e);
    if (!exited.entities.empty()) send(registry, ctx, client, {std::move(exited)});

    // Entities of assets are instantiated by the client from its copy of the asset.
    auto entered = std::vector<entity>{};
    auto entered_assets = packet::entity_entered{};
    for (auto e : interest.entities()) {
        if (!state.known.insert(e)) continue;
        if (registry.all_of<asset_ref>(e)) {
            entered_assets.assets.push_back(describe_asset(registry, e));
        } else if (!registry.all_of<asset_member>(e)) {
            entered.push_back(e);
        }
    }
    if (!entered_assets.assets.empty()) send(registry, ctx, client, {std::move(entered_assets)});
    send_create(registry, ctx, types, client, entered);
}

bool moving(const registry &registry, entity e) { return !registry.any_of<sleeping_tag, static_tag>(e); }

std::uint64_t hash_bytes(const std::vector<std::uint8_t> &bytes) {
    auto h = std::uint64_t{14695981039346656037ull};
    for (auto b : bytes)
        h = (h ^ b) * 1099511628211ull;
    return h;
}

// Whether to send `e`'s motion, encoded as `bytes`: when it differs from what was last sent to
// the client, in the change_repeats - 1 snapshots after that (so that one lost packet loses
// nothing), and otherwise in one snapshot of rest_refresh: a body resting in an island that is
// still awake costs a quarter, yet the client's copy, which its own simulation may have pushed
// (a misprediction), is put back soon.
bool motion_is_news(server_client_state &state, entity e, const std::vector<std::uint8_t> &bytes) {
    auto i = to_index(e);
    if (i >= state.sent.size()) state.sent.resize(std::size_t(i) + 1);
    auto &record = state.sent[i];
    if (record.e != e) record = {e, 0, 0, 0};
    auto hash = hash_bytes(bytes);
    if (hash != record.hash) {
        record.hash = hash;
        record.repeats = std::uint8_t(change_repeats - 1);
        record.skipped = 0;
        return true;
    }
    if (record.repeats > 0) {
        --record.repeats;
        return true;
    }
    if (++record.skipped < rest_refresh) return false;
    record.skipped = 0;
    return true;
}

// The other clients' inputs that wait in their jitter buffers, for the client's extrapolation:
// they are known here a playout delay before they apply, while the snapshot's values of them are
// those at its time. Each goes in the first forward_repeats snapshots after it arrived, and only
// if the client has all its entities; they are dropped from the buffers as they are applied, so
// none is older than the snapshot by more than a late packet.
void forward_inputs(const registry &registry, entity client, const server_client_state &state,
                    packet::registry_snapshot &snapshot) {
    for (auto [other, other_state] : registry.view<server_client_state>().each()) {
        if (other == client) continue;
        for (auto &buffered : other_state.jitter_buffer) {
            if (buffered.input_pools.empty() || buffered.arrival < state.recent_sends.front()) continue;
            if (snapshot.inputs.size() >= max_forwarded_inputs) return;
            auto known = std::all_of(buffered.entities.begin(), buffered.entities.end(),
                                     [&](entity e) { return state.known.contains(e); });
            if (known)
                snapshot.inputs.push_back({buffered.timestamp, buffered.entities, buffered.input_pools});
        }
    }
}

void send_snapshot(registry &registry, server_context &ctx, const network_registry &types, entity client,
                   const remote_client &rc, server_client_state &state) {
    auto now = get_simulation_time(registry);
    auto since = now - change_repeats / std::max(rc.snapshot_rate, 1e-3);
    auto writer = pool_writer(types, registry);
    auto &motion = types.types[network_index::motion];
    auto bytes = std::vector<std::uint8_t>{};
    for (auto e : state.known.entities()) {
        if (!registry.valid(e)) continue;
        if (motion.has(registry, e) &&
            (moving(registry, e) || types.changed_at(network_index::motion, e) >= since)) {
            bytes.clear();
            auto archive = memory_output_archive(bytes);
            motion.write(registry, e, {}, archive);
            if (motion_is_news(state, e, bytes)) writer.add_encoded(e, network_index::motion, bytes);
        }
        for (auto i = types.first_program_type; i < types.types.size(); ++i) {
            auto &t = types.types[i];
            if (t.action) continue;
            if (t.has(registry, e)) {
                if (types.changed_at(i, e) >= since) writer.add(e, i);
            } else if (types.removed_at(i, e) >= since) {
                writer.remove(e, i);
            }
        }
    }
    auto snapshot = packet::registry_snapshot{};
    snapshot.timestamp = now;
    writer.finish(snapshot.entities, snapshot.pools, snapshot.removed);
    forward_inputs(registry, client, state, snapshot);
    std::shift_left(state.recent_sends.begin(), state.recent_sends.end(), 1);
    state.recent_sends.back() = ++ctx.sequence;
    send(registry, ctx, client, {std::move(snapshot)});
}

void update_playout_delay(registry &registry, server_context &ctx, entity client, remote_client &rc,
                          server_client_state &state) {
    auto dt = double(get_fixed_dt(registry));
    if (state.playout_margin < 0) state.playout_margin = initial_playout_margin_steps * dt;
    rc.playout_delay = rc.round_trip_time / 2 + state.playout_margin;
    if (std::abs(rc.playout_delay - state.playout_sent) > 0.001) {
        state.playout_sent = rc.playout_delay;
        send(registry, ctx, client, {packet::set_playout_delay{rc.playout_delay}});
    }
}

// Applies the client's snapshots that are due, in time order.
void apply_due_snapshots(registry &registry, server_client_state &state, double now) {
    auto &types = registry.ctx().get<network_registry>();
    auto due = std::size_t{0};
    auto dt = double(get_fixed_dt(registry));
    while (due < state.jitter_buffer.size() &&
           detail::due_by_step(state.jitter_buffer[due].timestamp, now, dt))
        ++due;
    for (std::size_t i = 0; i < due; ++i) {
        auto &snapshot = state.jitter_buffer[i];
        apply_pools(registry, types, snapshot.pools, snapshot.entities, {});
        if (snapshot.has_inputs()) state.last_applied = snapshot.timestamp;
    }
    state.jitter_buffer.erase(state.jitter_buffer.begin(), state.jitter_buffer.begin() + std::ptrdiff_t(due));
}

// The state of an asset's entities, for a client that loaded the asset: the components each
// entity was assigned with.
void send_asset_state(registry &registry, server_context &ctx, entity client, remote_client &rc,
                      const server_client_state &state, entity asset) {
    if (!state.known.contains(asset) || !registry.valid(asset) || !registry.all_of<asset_ref>(asset)) {
        rc.rejected.unknown_entity += 1;
        return;
    }
    auto &types = registry.ctx().get<network_registry>();
    auto writer = pool_writer(types, registry);
    for (auto &[index, e] : registry.get<asset_ref>(asset).entities) {
        if (!registry.valid(e)) continue;
        writer.include(e);
        auto *member = registry.try_get<asset_member>(e);
        if (!member) continue;
        auto indices = std::vector<std::uint16_t>{};
        for (auto type : member->components) {
            // The transform and velocities travel together, quantised.
            auto i = types.index_of(type);
            if (type == type_index<position>() || type == type_index<orientation>() ||
                type == type_index<linvel>() || type == type_index<angvel>())
                i = network_index::motion;
            if (i >= 0 && types.types[std::size_t(i)].has(registry, e)) indices.push_back(std::uint16_t(i));
        }
        std::sort(indices.begin(), indices.end());
        indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
        for (auto i : indices)
            writer.add(e, i);
    }
    auto response = packet::asset_sync_response{};
    response.timestamp = get_simulation_time(registry);
    response.asset_entity = asset;
    writer.finish(response.entities, response.pools);
    send(registry, ctx, client, {std::move(response)});
}

void receive_snapshot(registry &registry, entity client, remote_client &rc, server_client_state &state,
                      const packet::registry_snapshot &snapshot) {
    // Forwarded inputs and removals are the server's to send. No client's time is further from
    // the server's than the longest playout delay (the other clients would refuse its inputs,
    // forwarded, and with them the snapshots that carry them).
    auto now = get_simulation_time(registry);
    if (!(std::abs(snapshot.timestamp - now) <= detail::max_playout_delay) || !snapshot.inputs.empty() ||
        !snapshot.removed.empty()) {
        rc.rejected.malformed += 1;
        return;
    }
    for (auto e : snapshot.entities) {
        if (!state.known.contains(e)) {
            rc.rejected.unknown_entity += 1;
            return;
        }
    }
    auto &types = registry.ctx().get<network_registry>();
    auto pools = decode_pools(types, snapshot.pools, snapshot.entities.size());
    if (!pools) {
        rc.rejected.malformed += 1;
        return;
    }
    for (auto &pool : *pools) {
        auto &t = types.types[pool->component_index];
        if (!t.input && !t.action) {
            rc.rejected.not_input += 1;
            return;
        }
        for (auto position : pool->positions) {
            if (!owns(rc, snapshot.entities[position])) {
                rc.rejected.not_owned += 1;
                return;
            }
        }
    }
    auto input_pools = std::vector<packet::pool_snapshot>{};
    for (std::size_t i = 0; i < pools->size(); ++i)
        if (types.types[(*pools)[i]->component_index].input) input_pools.push_back(snapshot.pools[i]);
    auto &buffer = state.jitter_buffer;
    auto at = std::upper_bound(buffer.begin(), buffer.end(), snapshot.timestamp,
                               [](double t, const buffered_snapshot &s) { return t < s.timestamp; });
    if (!input_pools.empty()) {
        // A copy of inputs applied (clients repeat their inputs), or inputs older than some
        // applied, which must not undo them.
        if (snapshot.timestamp <= state.last_applied) return;
        for (auto it = buffer.begin(); it != buffer.end(); ++it)
            if (it->has_inputs() && it->timestamp == snapshot.timestamp) return; // a copy
    }
    // Client times fall on the server's steps: a snapshot is late when its step has run (a copy
    // of inputs already applied was dropped above). How early the newest snapshots arrive keeps
    // the playout delay long enough: two in a row that arrive with less than the slack wanted
    // make it longer by what was missing, at once, so that the client's lead (and with it the
    // steps its inputs fall on) changes seldom. The slack wanted is half a step plus input_loss_cover
    // steps: each input goes in input_repeats packets a frame apart, so that it is still on time
    // when that many of them in a row are lost.
    auto dt = double(get_fixed_dt(registry));
    auto slack = snapshot.timestamp - now;
    if (state.playout_margin < 0) state.playout_margin = initial_playout_margin_steps * dt;
    if (slack < -dt / 2) rc.rejected.late += 1;
    if (snapshot.timestamp > state.newest_received) {
        state.newest_received = snapshot.timestamp;
        // Client times and the server's fall on its steps: half a step less against rounding.
        auto wanted = dt * (double(input_loss_cover) - 0.5);
        auto lack = std::max(wanted - slack, 0.0);
        auto both = std::min(lack, state.last_lack);
        state.last_lack = lack;
        if (both > 0) {
            if (now > state.growth_settles) {
                state.margin_before_growth = state.playout_margin;
                state.growth_settles = now + rc.round_trip_time + state.playout_margin + wanted + 2 * dt;
            }
            // A step more than was missing, so that the next packet only slightly later than
            // these does not make it grow again (each growth makes the client skip a step of
            // its inputs).
            auto needed = std::min(state.margin_before_growth + both + dt, max_playout_margin_steps * dt);
            state.playout_margin = std::max(state.playout_margin, needed);
        }
    }
    auto arrival = ++registry.ctx().get<server_context>().sequence;
    buffer.insert(at, buffered_snapshot{snapshot.timestamp, snapshot.entities, std::move(*pools),
                                        std::move(input_pools), arrival});
    if (buffer.size() > max_buffered_snapshots) buffer.erase(buffer.begin());
    (void)client;
}

} // namespace

void init_network_server(registry &registry) {
    if (!is_attached(registry))
        throw std::invalid_argument(
            "init_network_server: the registry is not attached (call edyn::attach first)");
    if (registry.ctx().contains<server_context>()) return;
    ensure_network_registry(registry).track_redefined = true;
    auto &ctx = registry.ctx().emplace<server_context>();
    ctx.settings_sent = current_settings(registry);
    registry.on_destroy<networked_tag>().connect<&on_networked_destroyed>();
}

void deinit_network_server(registry &registry) {
    if (!registry.ctx().contains<server_context>()) return;
    registry.on_destroy<networked_tag>().disconnect<&on_networked_destroyed>();
    auto &types = registry.ctx().get<network_registry>();
    types.track_redefined = false;
    types.redefined.clear();
    registry.clear<server_client_state>();
    registry.ctx().erase<server_context>();
}

sink<network_server_packet_signal> network_server_packet_sink(registry &registry) {
    return sink{get_server(registry, "network_server_packet_sink").packet_signal};
}

entity server_make_client(registry &registry) {
    auto &ctx = get_server(registry, "server_make_client");
    (void)ctx;
    auto client = registry.create();
    registry.emplace<remote_client>(client);
    // Clients take their snapshots on different steps (by entity index, over four steps), so that
    // the server's networking work is spread over steps instead of all falling on one.
    auto phase = double(to_index(client) % 4) * double(get_fixed_dt(registry));
    registry.emplace<server_client_state>(client).next_snapshot_time = get_simulation_time(registry) + phase;
    return client;
}

void server_set_client_round_trip_time(registry &registry, entity client, double rtt) {
    get_server(registry, "server_set_client_round_trip_time");
    auto &rc = get_client(registry, client, "server_set_client_round_trip_time");
    if (!(rtt >= 0) || !std::isfinite(rtt))
        throw std::invalid_argument("server_set_client_round_trip_time: rtt must be finite and >= 0, got " +
                                    std::to_string(rtt));
    rc.round_trip_time = rtt;
}

void server_set_client_snapshot_rate(registry &registry, entity client, double rate) {
    get_server(registry, "server_set_client_snapshot_rate");
    auto &rc = get_client(registry, client, "server_set_client_snapshot_rate");
    if (!valid_snapshot_rate(rate))
        throw std::invalid_argument("server_set_client_snapshot_rate: rate must be finite and > 0, got " +
                                    std::to_string(rate));
    rc.snapshot_rate = rate;
}

void server_receive_packet(registry &registry, entity client, const packet::edyn_packet &packet) {
    auto &ctx = get_server(registry, "server_receive_packet");
    auto &rc = get_client(registry, client, "server_receive_packet");
    auto &state = registry.get<server_client_state>(client);
    std::visit(
        [&](const auto &p) {
            using T = std::decay_t<decltype(p)>;
            if constexpr (std::is_same_v<T, packet::registry_snapshot>) {
                receive_snapshot(registry, client, rc, state, p);
            } else if constexpr (std::is_same_v<T, packet::time_request>) {
                send(registry, ctx, client, {packet::time_response{p.id, get_simulation_time(registry)}});
            } else if constexpr (std::is_same_v<T, packet::asset_sync>) {
                send_asset_state(registry, ctx, client, rc, state, p.asset_entity);
            } else if constexpr (std::is_same_v<T, packet::entity_request>) {
                if (p.entities.size() > max_requested_entities) {
                    rc.rejected.malformed += 1;
                    return;
                }
                auto entities = std::vector<entity>{};
                for (auto e : p.entities) {
                    if (state.known.contains(e)) {
                        if (registry.valid(e)) entities.push_back(e);
                        continue;
                    }
                    // An honest client names what it heard of before the entity left its
                    // interest or was destroyed: nothing is sent for it. Only an id the server
                    // never issued is refused.
                    if (!registry.valid(e) && !(to_version(e) < registry.current(e))) {
                        rc.rejected.unknown_entity += 1;
                        return;
                    }
                }
                send_create(registry, ctx, registry.ctx().get<network_registry>(), client, entities);
            } else {
                // Entities, settings and clocks are the server's to send.
                rc.rejected.not_input += 1;
            }
        },
        packet.var);
}

void update_network_server(registry &registry) {
    auto &ctx = get_server(registry, "update_network_server");
    // The program may write remote_client::snapshot_rate directly: a NaN would stop the client's
    // snapshots, a rate <= 0 send one per 1000 s. Refused before anything is done.
    for (auto [client, rc] : registry.view<remote_client>().each()) {
        if (!valid_snapshot_rate(rc.snapshot_rate))
            throw std::invalid_argument("update_network_server: remote_client::snapshot_rate of entity " +
                                        std::to_string(to_index(client)) + " must be finite and > 0, got " +
                                        std::to_string(rc.snapshot_rate));
        // A NaN or inverted box would hold nothing: the client would silently be sent no body.
        auto &box = rc.aabb_of_interest;
        if (!isfinite(box.min) || !isfinite(box.max) ||
            !(box.min.x <= box.max.x && box.min.y <= box.max.y && box.min.z <= box.max.z))
            throw std::invalid_argument("update_network_server: remote_client::aabb_of_interest of entity " +
                                        std::to_string(to_index(client)) +
                                        " must be finite with min <= max on every axis");
    }
    auto &types = registry.ctx().get<network_registry>();
    auto now = get_simulation_time(registry);
    types.now = now;

    auto settings = current_settings(registry);
    auto settings_changed = settings != ctx.settings_sent;
    ctx.settings_sent = settings;

    ctx.boxes_ready = false;
    auto destroyed = std::move(ctx.destroyed);
    ctx.destroyed.clear();
    // What the program changed in bodies and constraints the clients have goes to them once,
    // reliably, as their values in a create_entity (a client updates what it has).
    ctx.redefined.clear();
    for (auto e : types.redefined)
        if (registry.valid(e) && registry.all_of<networked_tag>(e)) ctx.redefined.insert(e);
    types.redefined.clear();

    for (auto [client, rc, state] : registry.view<remote_client, server_client_state>().each()) {
        if (!state.greeted) {
            state.greeted = true;
            send(registry, ctx, client, {packet::client_created{client}});
            send(registry, ctx, client, {settings});
        } else if (settings_changed) {
            send(registry, ctx, client, {settings});
        }
        if (!destroyed.empty()) {
            auto packet = packet::destroy_entity{now, {}};
            for (auto e : destroyed)
                if (state.known.erase(e)) packet.entities.push_back(e);
            if (!packet.entities.empty()) send(registry, ctx, client, {std::move(packet)});
        }
        if (ctx.redefined.size() > 0) {
            auto known = std::vector<entity>{};
            for (auto e : ctx.redefined.entities())
                if (state.known.contains(e)) known.push_back(e);
            send_create(registry, ctx, types, client, known);
        }
        // Actions among them go into the entities' action_lists, for the next step.
        apply_due_snapshots(registry, state, now);
        update_playout_delay(registry, ctx, client, rc, state);
        if (now >= state.next_snapshot_time) {
            state.next_snapshot_time = now + 1 / std::max(rc.snapshot_rate, 1e-3) - 1e-9;
            update_interest(registry, ctx, types, client, rc, state);
            send_snapshot(registry, ctx, types, client, rc, state);
        }
    }
}

} // namespace edyn
