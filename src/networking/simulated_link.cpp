#include "edyn/networking/simulated_link.hpp"
#include "../shapes/invalid_argument.hpp"
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace edyn {

namespace {

void check_time(const char *field, double value) {
    if (!std::isfinite(value) || value < 0) {
        detail::throw_invalid_argument("simulated_link: ", field, " must be finite and >= 0, got ", value);
    }
}

void check_probability(const char *field, double value) {
    // Written so that NaN fails too.
    if (!(value >= 0 && value <= 1)) {
        detail::throw_invalid_argument("simulated_link: ", field, " must be in [0, 1], got ", value);
    }
}

// Min-heap order for std::push_heap/pop_heap, which build max-heaps: "a after b".
struct later {
    template<typename Delivery>
    bool operator()(const Delivery &a, const Delivery &b) const noexcept {
        return a.time != b.time ? a.time > b.time : a.sequence > b.sequence;
    }
};

} // namespace

simulated_link::simulated_link(const simulated_link_settings &settings)
    : config(settings)
    , rng(settings.seed)
    , last_send_time(-std::numeric_limits<double>::infinity())
    , last_reliable_time(-std::numeric_limits<double>::infinity()) {
    check_time("latency", settings.latency);
    check_time("jitter", settings.jitter);
    check_time("reorder_delay", settings.reorder_delay);
    check_probability("loss", settings.loss);
    check_probability("duplication", settings.duplication);
    check_probability("reordering", settings.reordering);
}

// The top 53 bits of one draw scaled into [0, 1): exact in a double and the same everywhere,
// unlike std::uniform_real_distribution whose algorithm the standard leaves open.
double simulated_link::uniform01() { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

double simulated_link::sample_delay() {
    auto offset = config.jitter * (2 * uniform01() - 1);
    return std::max(0.0, config.latency + offset);
}

double simulated_link::hold_back(bool held_back) {
    if (!held_back) return 0;
    ++counters.packets_reordered;
    return config.reorder_delay;
}

void simulated_link::schedule(double time, std::vector<std::uint8_t> data) {
    queue.push_back(delivery{time, next_sequence++, std::move(data)});
    std::push_heap(queue.begin(), queue.end(), later{});
}

// Every send draws its random numbers in a fixed order (loss, delay, reorder, duplication, then
// the extra ones a resend or copy needs), so a given seed gives the same run on every platform
// and changing one probability does not reshuffle the draws of unrelated packets.
void simulated_link::send(double now, std::vector<std::uint8_t> data, bool reliable) {
    if (!std::isfinite(now) || now < last_send_time) {
        detail::throw_invalid_argument(
            "simulated_link::send: now must be finite and not less than the previous ", last_send_time,
            ", got ", now);
    }
    last_send_time = now;
    ++counters.packets_sent;
    counters.bytes_sent += data.size();

    auto lost = uniform01() < config.loss;
    auto delay = sample_delay();
    auto held_back = uniform01() < config.reordering;
    auto duplicated = uniform01() < config.duplication;

    if (reliable) {
        auto time = now + delay;
        if (lost) {
            // The sender notices the missing acknowledgement a round trip after sending and
            // resends; that attempt crosses the wire with a delay of its own.
            ++counters.retransmissions;
            time = now + 2 * config.latency + sample_delay();
        }
        time += hold_back(held_back);
        // The receiver hands reliable packets over in sequence, waiting for any earlier one.
        time = std::max(time, last_reliable_time);
        last_reliable_time = time;
        schedule(time, std::move(data));
        return;
    }

    if (lost) {
        ++counters.packets_lost;
        return;
    }
    auto time = now + delay + hold_back(held_back);
    if (duplicated) {
        ++counters.packets_duplicated;
        auto copy_delay = sample_delay();
        auto copy_time = now + copy_delay + hold_back(uniform01() < config.reordering);
        schedule(time, data);
        schedule(copy_time, std::move(data));
        return;
    }
    schedule(time, std::move(data));
}

std::vector<std::vector<std::uint8_t>> simulated_link::receive(double now) {
    std::vector<std::vector<std::uint8_t>> due;
    while (!queue.empty() && queue.front().time <= now) {
        std::pop_heap(queue.begin(), queue.end(), later{});
        auto &last = queue.back();
        ++counters.packets_delivered;
        counters.bytes_delivered += last.data.size();
        due.push_back(std::move(last.data));
        queue.pop_back();
    }
    return due;
}

} // namespace edyn
