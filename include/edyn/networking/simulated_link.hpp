#ifndef EDYN_NETWORKING_SIMULATED_LINK_HPP
#define EDYN_NETWORKING_SIMULATED_LINK_HPP

#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace edyn {

// How bad the simulated network is. Times in seconds, probabilities in [0, 1].
struct simulated_link_settings {
    double latency{0.05};       // one-way delay (half the round-trip time), >= 0
    double jitter{0};           // each delay is uniform in [latency - jitter, latency + jitter], clamped at 0
    double loss{0};             // probability that a packet is lost on the wire
    double duplication{0};      // probability that an unreliable packet that got through arrives twice
    double reordering{0};       // probability that a delivery is held back an extra `reorder_delay`
    double reorder_delay{0.03}; // >= 0
    std::uint64_t seed{1};
};

struct simulated_link_stats {
    std::uint64_t packets_sent{0};
    std::uint64_t bytes_sent{0};
    std::uint64_t packets_lost{0};       // unreliable packets dropped (reliable ones are resent instead)
    std::uint64_t packets_duplicated{0}; // extra copies scheduled
    std::uint64_t packets_reordered{0};  // deliveries (copies included) held back by `reorder_delay`
    std::uint64_t packets_delivered{0};  // returned by receive(), copies included
    std::uint64_t bytes_delivered{0};
    std::uint64_t retransmissions{0}; // reliable packets whose first attempt was lost
};

// One direction of an unreliable network between in-process peers, for tests and benchmarks:
// packets sent now come out of receive() later, some lost, duplicated or out of order, all
// decided by a seeded std::mt19937_64 so a run repeats bit for bit on every platform.
//
// Reliable packets behave like one ENet reliable channel as the application sees it: never lost
// (a lost attempt arrives a round trip later, as the resend would), never duplicated (the
// receiver discards copies), and delivered in send order relative to each other, so one held-back
// reliable packet holds back the reliable ones after it.
class simulated_link {
public:
    // Throws std::invalid_argument naming "simulated_link", the field and its value when a time
    // is negative or not finite or a probability is outside [0, 1].
    explicit simulated_link(const simulated_link_settings &settings = {});

    // Sends `data` at time `now` (seconds). `now` must be finite and not less than in the previous
    // call; otherwise throws std::invalid_argument.
    void send(double now, std::vector<std::uint8_t> data, bool reliable);

    // Packets due at or before `now`, in delivery-time order (ties in send order).
    std::vector<std::vector<std::uint8_t>> receive(double now);

    // Deliveries scheduled but not yet received (duplicate copies counted separately).
    std::size_t in_flight() const noexcept { return queue.size(); }
    const simulated_link_stats &stats() const noexcept { return counters; }
    const simulated_link_settings &settings() const noexcept { return config; }

private:
    struct delivery {
        double time;
        std::uint64_t sequence; // schedule order, breaks ties so equal times come out in send order
        std::vector<std::uint8_t> data;
    };

    double uniform01();
    double sample_delay();
    double hold_back(bool held_back); // the extra delay, counted when held back
    void schedule(double time, std::vector<std::uint8_t> data);

    simulated_link_settings config;
    simulated_link_stats counters;
    std::mt19937_64 rng;
    std::vector<delivery> queue; // binary min-heap on (time, sequence)
    std::uint64_t next_sequence{0};
    double last_send_time;
    double last_reliable_time; // delivery time of the latest reliable packet, for ordering
};

} // namespace edyn

#endif // EDYN_NETWORKING_SIMULATED_LINK_HPP
