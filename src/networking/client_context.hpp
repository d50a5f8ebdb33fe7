#ifndef EDYN_SRC_NETWORKING_CLIENT_CONTEXT_HPP
#define EDYN_SRC_NETWORKING_CLIENT_CONTEXT_HPP

// A network client's state, in its registry's context, shared by client.cpp (packets, updates,
// snapshots), client_extrapolation.cpp and client_assets.cpp.

#include "edyn/ecs/entity_map.hpp"
#include "edyn/networking/client.hpp"
#include "edyn/parallel/background_job.hpp"
#include "edyn/simulation/world.hpp"
#include "entity_set.hpp"
#include "extrapolation.hpp"
#include "network_registry.hpp"
#include "step_time.hpp"
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace edyn::client_detail {

// A change is sent in this many consecutive snapshots, so that one lost packet loses nothing.
inline constexpr double change_repeats = 3;
// Actions and recorded inputs are kept this long (seconds of server time).
inline constexpr double history_length = 1;
inline constexpr double time_request_interval = 1;
// Clock samples: the clock offset comes from the first this many, asked for one a frame; later
// ones, one every time_request_interval, only tell a new clock (a server restarted). The clocks
// of client and server run at the same rate, so the offset does not change, and keeping it
// keeps the client's lead still (each move up skips steps of its inputs); how late the client's
// packets arrive after all, the server answers with a longer playout delay.
inline constexpr std::size_t offset_samples_wanted = 9;
// Time requests awaiting a reply at once, at most.
inline constexpr std::size_t max_pending_time_requests = 16;
// An entity a snapshot names before its create_entity arrived is asked for again after this.
inline constexpr double entity_request_interval = 0.5;
inline constexpr int max_lead_steps = 4;
// A result this many steps old is still carried forward; an older one is dropped.
inline constexpr long long max_carried_steps = 2;
// Bounds on the times a server sends (seconds), past which its packets are refused: its
// simulation time (an uptime, from 0 at attach), how far ahead of the client's time a snapshot
// may be (snapshots are of the server's past; a larger lead is a clock the next time response
// corrects), and the playout delay (half a round trip and a few steps).
inline constexpr double max_server_time = 1e9;
inline constexpr double max_snapshot_lead = 2;
using detail::max_playout_delay;
// Most forwarded inputs of other clients kept at once: twice the most a snapshot carries.
inline constexpr std::size_t max_kept_forwarded = 512;

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
    // One reply of the server's clock: the offset it gives and the round trip it took.
    struct clock_sample {
        double offset;
        double round_trip;
    };
    std::vector<clock_sample> offset_samples; // the first offset_samples_wanted, in arrival order
    // clock_offset + playout_delay in whole steps, rounded up: how far the client's time runs
    // ahead of its local simulation time (see update_lead).
    long long clock_lead_steps{0};
    std::uint32_t next_request_id{1};
    // Time requests sent and not answered yet: id and local time sent.
    struct pending_time_request {
        std::uint32_t id;
        double sent;
    };
    std::vector<pending_time_request> pending_time_requests;
    double next_time_request{-std::numeric_limits<double>::infinity()};
    double next_snapshot_time{-std::numeric_limits<double>::infinity()};

    // The newest server motion of each body, by local entity index. The server sends a body only
    // when its motion changed (and now and then when it did not), so the newest value of each
    // is the server's state at the newest snapshot's time, which the extrapolation starts from.
    struct server_motion {
        entity local{null};
        double time{-std::numeric_limits<double>::infinity()};
        network_motion motion;
    };
    std::vector<server_motion> motions;
    // Per network index of the program's types, by local entity index: the time of the snapshot
    // whose value (or removal) the entity has, so that an older snapshot arriving late does not
    // undo a newer one.
    std::vector<std::vector<std::pair<entity, double>>> value_times;
    // Whether a snapshot newer than the last extrapolation's start arrived, and its time.
    bool has_pending{false};
    double pending_time{-std::numeric_limits<double>::infinity()};
    std::vector<std::pair<entity, double>> requested; // remote entity, time asked

    // The client's inputs, oldest first, addressed to the server's entities: sent to the server
    // (each in the snapshots of the next change_repeats periods) and re-applied by the
    // extrapolation.
    struct recorded_input {
        double time;
        std::vector<entity> entities;
        std::vector<packet::pool_snapshot> pools;
        // Updates left that send it again.
        int sends_left{0};
    };
    std::vector<recorded_input> inputs;
    double last_input_record{-std::numeric_limits<double>::infinity()};
    // Other clients' inputs the server forwarded (packet::registry_snapshot::inputs) and has not
    // applied before the newest snapshot's step, oldest first: the extrapolation applies them at
    // their times.
    std::vector<recorded_input> forwarded;

    std::uint64_t decay_step{0};

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

inline client_context &get_client(registry &registry, const char *function) {
    auto *ctx = registry.ctx().find<client_context>();
    if (!ctx)
        throw std::invalid_argument(std::string(function) + ": the registry is not a network client "
                                                            "(call init_network_client first)");
    return *ctx;
}

inline const client_context &get_client(const registry &registry, const char *function) {
    return get_client(const_cast<edyn::registry &>(registry), function);
}

// The server time the client is at: its local time plus its lead, in whole steps so that its
// inputs and extrapolations fall on the server's steps (both clocks advance in steps of the same
// fixed dt).
inline double client_time(const registry &registry, const client_context &ctx) {
    return get_simulation_time(registry) + double(ctx.clock_lead_steps) * double(get_fixed_dt(registry));
}

// Keeps clock_lead_steps at the current estimate rounded up to a whole step: a lead short of it
// makes inputs arrive after their step (lost); a longer one only makes them wait, and the server
// makes the playout delay longer when they arrive with too little time to spare. Moving down
// makes the client's time repeat a step (inputs stamped with a time already sent are copies);
// moving up makes it skip steps, on which the server keeps the inputs before them. The estimate
// moves seldom: the playout delay only grows, and the clock offset is settled from the first
// samples (see receive_time).
inline void update_lead(const registry &registry, client_context &ctx) {
    auto target = (ctx.clock_offset + ctx.playout_delay) / double(get_fixed_dt(registry));
    ctx.clock_lead_steps = std::llround(std::ceil(target - 1e-6));
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

inline std::vector<entity> to_local(const client_context &ctx, const std::vector<entity> &remote) {
    auto local = std::vector<entity>(remote.size(), entity{null});
    for (std::size_t i = 0; i < remote.size(); ++i)
        local[i] = ctx.remote_to_local.find(remote[i]);
    return local;
}

inline detail::entity_mapper remote_to_local_map(const client_context &ctx) {
    return [&ctx](entity e) { return ctx.remote_to_local.find(e); };
}

// client.cpp
// Destroys the local entities of these remote ones, and forgets their mapping.
void destroy_local(registry &registry, client_context &ctx, const std::vector<entity> &remote);
// Whether remote entity `remote` may be given a local entity. The server reuses an index only
// once it has destroyed the entity that had it: where the client maps an older version of
// `remote`'s index, that entity is gone, though its destroy_entity or entity_exited has yet to
// arrive, and its local entity is destroyed now. Where it maps a newer version, `remote` comes
// from a packet that arrived late, and is not mapped.
bool make_room_for(registry &registry, client_context &ctx, entity remote);

// client_extrapolation.cpp
void decay_discontinuities(registry &registry, client_context &ctx);
void start_extrapolation(registry &registry, client_context &ctx, network_registry &types, double now);
bool merge_extrapolation(registry &registry, client_context &ctx, double now);

// client_assets.cpp
void receive_entered(registry &registry, client_context &ctx, const packet::entity_entered &entered);
void receive_asset_state(registry &registry, client_context &ctx,
                         const packet::asset_sync_response &response);

} // namespace edyn::client_detail

#endif // EDYN_SRC_NETWORKING_CLIENT_CONTEXT_HPP
