#ifndef EDYN_NETWORKING_SIMULATED_LINK_HPP
#define EDYN_NETWORKING_SIMULATED_LINK_HPP

#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace edyn {

/// How bad the simulated network is: the settings of a simulated_link. Times in seconds,
/// probabilities in [0, 1]; the constructor of simulated_link checks them.
struct simulated_link_settings {
    double latency{0.05};       ///< One-way delay (half the round-trip time), >= 0 (default 0.05 s).
    double jitter{0};           ///< Each delay is uniform in latency ± jitter (s, >= 0), clamped at 0.
    double loss{0};             ///< Probability that a packet is lost on the wire.
    double duplication{0};      ///< Probability that an unreliable packet that got through arrives twice.
    double reordering{0};       ///< Probability that a delivery is held back an extra `reorder_delay`.
    double reorder_delay{0.03}; ///< Extra delay of a held-back delivery, >= 0 (default 0.03 s).
    std::uint64_t seed{1};      ///< Seed of the random generator: the same seed gives the same run.
};

/// What a simulated_link did so far; every count starts at 0.
struct simulated_link_stats {
    std::uint64_t packets_sent{0};       ///< Calls to send().
    std::uint64_t bytes_sent{0};         ///< Bytes given to send().
    std::uint64_t packets_lost{0};       ///< Unreliable packets dropped (reliable ones are resent instead).
    std::uint64_t packets_duplicated{0}; ///< Extra copies scheduled.
    std::uint64_t packets_reordered{0};  ///< Deliveries (copies included) held back by `reorder_delay`.
    std::uint64_t packets_delivered{0};  ///< Returned by receive(), copies included.
    std::uint64_t bytes_delivered{0};    ///< Bytes returned by receive(), copies included.
    std::uint64_t retransmissions{0};    ///< Reliable packets whose first attempt was lost.
};

/// One direction of an unreliable network between in-process peers, for tests and benchmarks.
///
/// Packets sent now come out of receive() later, some lost, duplicated or out of order, all
/// decided by a seeded `std::mt19937_64` so a run repeats bit for bit on every platform.
///
/// Reliable packets behave like one ENet reliable channel as the application sees it: never lost
/// (a lost attempt arrives a round trip later, as the resend would), never duplicated (the
/// receiver discards copies), and delivered in send order relative to each other, so one held-back
/// reliable packet holds back the reliable ones after it.
///
/// Not thread-safe: use one link from one thread at a time.
class simulated_link {
public:
    /// Makes a link with the given behaviour and nothing in flight.
    /// @param settings Delays, probabilities and seed (the defaults: 50 ms latency, nothing lost).
    /// @throws std::invalid_argument Naming "simulated_link", the field and its value when a time
    /// (latency, jitter, reorder_delay) is negative or not finite or a probability (loss,
    /// duplication, reordering) is outside [0, 1].
    explicit simulated_link(const simulated_link_settings &settings = {});

    /// Sends a packet; it comes out of receive() after its delay, unless lost.
    /// @param now The sender's time in seconds.
    /// @param data The packet's bytes.
    /// @param reliable Whether the packet must arrive (see the class description).
    /// @throws std::invalid_argument When `now` is not finite or less than in the previous call.
    void send(double now, std::vector<std::uint8_t> data, bool reliable);

    /// Takes the packets that have arrived.
    /// @param now The receiver's time in seconds (the same clock as send()'s).
    /// @return Packets due at or before `now`, in delivery-time order (ties in send order).
    std::vector<std::vector<std::uint8_t>> receive(double now);

    /// Deliveries scheduled but not yet received (duplicate copies counted separately).
    /// @return The number of deliveries in flight.
    std::size_t in_flight() const noexcept { return queue.size(); }
    /// What the link did so far.
    /// @return The counts, updated by send() and receive().
    const simulated_link_stats &stats() const noexcept { return counters; }
    /// The settings the link was made with.
    /// @return The settings given to the constructor.
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
