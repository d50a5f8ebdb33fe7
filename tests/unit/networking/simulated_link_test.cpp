// The simulated unreliable network link (simulated_link.hpp): latency, jitter, loss,
// duplication, reordering, the reliable channel, determinism and settings validation.
#include <cmath>
#include <cstdint>
#include <edyn/networking/simulated_link.hpp>
#include <functional>
#include <gtest/gtest.h>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

using namespace edyn;

namespace {

std::vector<std::uint8_t> payload(std::uint32_t id) {
    return {std::uint8_t(id), std::uint8_t(id >> 8), std::uint8_t(id >> 16), std::uint8_t(id >> 24)};
}

std::uint32_t id_of(const std::vector<std::uint8_t> &data) {
    return std::uint32_t(data[0]) | std::uint32_t(data[1]) << 8 | std::uint32_t(data[2]) << 16 |
           std::uint32_t(data[3]) << 24;
}

struct arrival {
    std::uint32_t id;
    std::int64_t tick; // receive() call that returned it
};

struct schedule {
    std::uint32_t count;
    std::int64_t ticks_between_sends;
    double tick; // seconds between receive() calls
    bool reliable;
};

// Packet i is sent at tick i * ticks_between_sends; receive() is called every tick (after that
// tick's send) until nothing is in flight. Times are tick * s.tick, computed one way for both
// sends and receives, so a delay is measured as (arrival tick - send tick) * s.tick, at most one
// tick above the real one and never below.
std::vector<arrival> drive(simulated_link &link, const schedule &s) {
    std::vector<arrival> arrivals;
    std::uint32_t sent = 0;
    for (std::int64_t k = 0; sent < s.count || link.in_flight() > 0; ++k) {
        auto now = double(k) * s.tick;
        if (sent < s.count && k % s.ticks_between_sends == 0) {
            link.send(now, payload(sent++), s.reliable);
        }
        for (auto &data : link.receive(now)) {
            arrivals.push_back({id_of(data), k});
        }
    }
    return arrivals;
}

double delay_of(const arrival &a, const schedule &s) {
    return double(a.tick - std::int64_t(a.id) * s.ticks_between_sends) * s.tick;
}

std::vector<int> copies_per_id(const std::vector<arrival> &arrivals, std::uint32_t count) {
    std::vector<int> copies(count, 0);
    for (auto &a : arrivals)
        ++copies[a.id];
    return copies;
}

// Pairs (i, j) with i before j in arrival order but sent after j, counted between neighbours.
int adjacent_inversions(const std::vector<arrival> &arrivals) {
    int inversions = 0;
    for (std::size_t i = 1; i < arrivals.size(); ++i) {
        if (arrivals[i].id < arrivals[i - 1].id) ++inversions;
    }
    return inversions;
}

} // namespace

TEST(simulated_link, without_impairments_delivers_everything_exactly_after_latency_in_send_order) {
    simulated_link_settings settings;
    settings.latency = 0.05;
    simulated_link link(settings);
    const std::uint32_t count = 100;
    for (std::uint32_t i = 0; i < count; ++i) {
        link.send(i * 0.01, payload(i), i % 2 == 0);
    }
    EXPECT_EQ(link.in_flight(), count);

    for (std::uint32_t i = 0; i < count; ++i) {
        auto due = i * 0.01 + settings.latency;
        auto early = link.receive(std::nextafter(due, 0.0));
        EXPECT_TRUE(early.empty()) << "packet " << i << ": " << early.size()
                                   << " packets delivered just before its due time " << due << ", expected 0";
        auto now = link.receive(due);
        ASSERT_EQ(now.size(), 1u) << "packet " << i << " at its due time " << due;
        EXPECT_EQ(id_of(now[0]), i) << "measured packet " << id_of(now[0]) << ", expected " << i;
    }
    EXPECT_EQ(link.in_flight(), 0u);

    auto &stats = link.stats();
    EXPECT_EQ(stats.packets_sent, count);
    EXPECT_EQ(stats.bytes_sent, 4u * count);
    EXPECT_EQ(stats.packets_delivered, count);
    EXPECT_EQ(stats.bytes_delivered, 4u * count);
    EXPECT_EQ(stats.packets_lost, 0u);
    EXPECT_EQ(stats.packets_duplicated, 0u);
    EXPECT_EQ(stats.packets_reordered, 0u);
    EXPECT_EQ(stats.retransmissions, 0u);
}

TEST(simulated_link, nothing_is_delivered_before_its_shortest_possible_delay) {
    simulated_link_settings settings;
    settings.latency = 0.04;
    settings.jitter = 0.015;
    settings.loss = 0.2;
    settings.duplication = 0.2;
    settings.reordering = 0.2;
    settings.seed = 7;
    const double shortest = settings.latency - settings.jitter;
    for (bool reliable : {false, true}) {
        simulated_link link(settings);
        schedule s{5000, 5, 0.001, reliable};
        auto arrivals = drive(link, s);
        ASSERT_FALSE(arrivals.empty());
        double min_delay = std::numeric_limits<double>::infinity();
        for (auto &a : arrivals)
            min_delay = std::min(min_delay, delay_of(a, s));
        EXPECT_GE(min_delay, shortest - 1e-9)
            << (reliable ? "reliable" : "unreliable") << ": measured shortest delay " << min_delay
            << " s, expected at least latency - jitter = " << shortest << " s";
    }
}

TEST(simulated_link, measured_loss_rate_matches_setting) {
    for (double loss : {0.0, 0.1, 0.3}) {
        simulated_link_settings settings;
        settings.loss = loss;
        settings.jitter = 0.01;
        simulated_link link(settings);
        schedule s{20000, 1, 0.001, false};
        auto arrivals = drive(link, s);
        auto measured = 1 - double(arrivals.size()) / s.count;
        EXPECT_NEAR(measured, loss, 0.015) << "measured loss rate " << measured << ", expected " << loss;
        EXPECT_EQ(link.stats().packets_lost, s.count - arrivals.size())
            << "packets_lost counts what did not arrive";
        EXPECT_EQ(link.stats().packets_delivered, arrivals.size());
    }
}

TEST(simulated_link, measured_duplication_rate_matches_setting) {
    for (double duplication : {0.0, 0.05, 0.25}) {
        simulated_link_settings settings;
        settings.duplication = duplication;
        settings.jitter = 0.01;
        simulated_link link(settings);
        schedule s{20000, 1, 0.001, false};
        auto arrivals = drive(link, s);
        auto copies = copies_per_id(arrivals, s.count);
        std::uint32_t twice = 0;
        for (auto c : copies) {
            ASSERT_GE(c, 1) << "a packet was lost with loss = 0";
            ASSERT_LE(c, 2) << "a packet arrived more than twice";
            if (c == 2) ++twice;
        }
        auto measured = double(twice) / s.count;
        EXPECT_NEAR(measured, duplication, 0.015)
            << "measured duplication rate " << measured << ", expected " << duplication;
        EXPECT_EQ(link.stats().packets_duplicated, twice);
        EXPECT_EQ(link.stats().packets_delivered, s.count + twice);
    }
}

TEST(simulated_link, jitter_keeps_every_delay_within_bounds_and_varies) {
    simulated_link_settings settings;
    settings.latency = 0.05;
    settings.jitter = 0.02;
    settings.seed = 3;
    simulated_link link(settings);
    schedule s{5000, 10, 0.0001, false};
    auto arrivals = drive(link, s);
    ASSERT_EQ(arrivals.size(), s.count);

    const double low = settings.latency - settings.jitter;
    const double high = settings.latency + settings.jitter;
    double min_delay = std::numeric_limits<double>::infinity();
    double max_delay = 0;
    for (auto &a : arrivals) {
        auto delay = delay_of(a, s);
        min_delay = std::min(min_delay, delay);
        max_delay = std::max(max_delay, delay);
    }
    // Measured delays round up to the next tick.
    EXPECT_GE(min_delay, low - 1e-9) << "measured shortest delay " << min_delay << ", expected >= " << low;
    EXPECT_LE(max_delay, high + s.tick + 1e-9)
        << "measured longest delay " << max_delay << ", expected <= " << high;
    // Uniform over 400 ticks: 5000 draws come close to both ends.
    EXPECT_LT(min_delay, low + 0.002) << "measured shortest delay " << min_delay << ", expected near " << low;
    EXPECT_GT(max_delay, high - 0.002)
        << "measured longest delay " << max_delay << ", expected near " << high;
    EXPECT_GT(adjacent_inversions(arrivals), 0) << "jitter larger than the send interval should reorder";
}

TEST(simulated_link, jitter_larger_than_latency_clamps_delay_at_zero) {
    simulated_link_settings settings;
    settings.latency = 0.01;
    settings.jitter = 0.05;
    simulated_link link(settings);
    int immediate = 0;
    const int count = 1000;
    for (int i = 0; i < count; ++i) {
        link.send(i * 0.1, payload(std::uint32_t(i)), false);
        immediate += int(link.receive(i * 0.1).size());
        link.receive(i * 0.1 + 0.06); // everything else, before the next send
    }
    // Delays below zero, (0.05 - 0.01) / 0.1 = 40% of the draws, all arrive at once.
    EXPECT_NEAR(double(immediate) / count, 0.4, 0.05)
        << "measured share delivered with zero delay " << double(immediate) / count << ", expected 0.4";
    EXPECT_EQ(link.in_flight(), 0u);
}

TEST(simulated_link, reliable_packets_are_never_lost_and_arrive_once_in_send_order) {
    simulated_link_settings settings;
    settings.latency = 0.03;
    settings.jitter = 0.02;
    settings.loss = 0.5;
    settings.duplication = 0.3;
    settings.reordering = 0.2;
    settings.seed = 11;
    simulated_link link(settings);
    schedule s{20000, 1, 0.001, true};
    auto arrivals = drive(link, s);

    ASSERT_EQ(arrivals.size(), s.count) << "measured deliveries, expected one per reliable packet";
    for (std::uint32_t i = 0; i < s.count; ++i) {
        ASSERT_EQ(arrivals[i].id, i) << "measured packet " << arrivals[i].id << " in place " << i
                                     << ", expected " << i;
    }
    auto &stats = link.stats();
    EXPECT_EQ(stats.packets_lost, 0u);
    EXPECT_EQ(stats.packets_duplicated, 0u);
    auto measured = double(stats.retransmissions) / s.count;
    EXPECT_NEAR(measured, settings.loss, 0.015)
        << "measured retransmission rate " << measured << ", expected the loss " << settings.loss;
}

TEST(simulated_link, lost_reliable_attempt_arrives_one_round_trip_later) {
    simulated_link_settings settings;
    settings.latency = 0.05;
    settings.loss = 1;
    simulated_link link(settings);
    link.send(1.0, payload(42), true);
    // The link adds the round trip and the resend's delay separately: allow their rounding.
    const double expected = 1.0 + 3 * settings.latency;
    EXPECT_TRUE(link.receive(expected - 1e-12).empty())
        << "delivered before send time + latency + round trip = " << expected;
    auto due = link.receive(expected + 1e-12);
    ASSERT_EQ(due.size(), 1u) << "measured deliveries at " << expected << ", expected 1";
    EXPECT_EQ(id_of(due[0]), 42u);
    EXPECT_EQ(link.stats().retransmissions, 1u);
}

TEST(simulated_link, reordering_reorders_some_unreliable_packets) {
    simulated_link_settings settings;
    settings.latency = 0.05;
    settings.reordering = 0.1;
    settings.reorder_delay = 0.03;
    simulated_link link(settings);
    schedule s{20000, 1, 0.001, false};
    auto arrivals = drive(link, s);
    ASSERT_EQ(arrivals.size(), s.count);
    auto inversions = adjacent_inversions(arrivals);
    EXPECT_GT(inversions, 0) << "measured " << inversions << " out-of-order arrivals, expected some";
    auto measured = double(link.stats().packets_reordered) / s.count;
    EXPECT_NEAR(measured, settings.reordering, 0.015)
        << "measured held-back rate " << measured << ", expected " << settings.reordering;

    settings.reordering = 0;
    simulated_link in_order(settings);
    auto ordered = drive(in_order, s);
    EXPECT_EQ(adjacent_inversions(ordered), 0) << "reordering = 0 without jitter must keep send order";
}

TEST(simulated_link, same_seed_repeats_and_different_seed_differs) {
    simulated_link_settings settings;
    settings.latency = 0.04;
    settings.jitter = 0.01;
    settings.loss = 0.1;
    settings.duplication = 0.1;
    settings.reordering = 0.1;
    settings.seed = 1234;
    schedule s{3000, 2, 0.001, false};
    auto run = [&](std::uint64_t seed) {
        settings.seed = seed;
        simulated_link link(settings);
        return drive(link, s);
    };
    auto same = [](const std::vector<arrival> &a, const std::vector<arrival> &b) {
        if (a.size() != b.size()) return false;
        for (std::size_t i = 0; i < a.size(); ++i) {
            if (a[i].id != b[i].id || a[i].tick != b[i].tick) return false;
        }
        return true;
    };
    auto first = run(1234);
    auto second = run(1234);
    auto other = run(1235);
    EXPECT_TRUE(same(first, second)) << "same seed: measured " << first.size() << " and " << second.size()
                                     << " deliveries, expected identical sequences";
    EXPECT_FALSE(same(first, other)) << "different seeds gave identical sequences of " << first.size()
                                     << " deliveries, expected them to differ";
}

TEST(simulated_link, invalid_settings_throw_naming_the_field_and_value) {
    struct bad_setting {
        std::string field;
        std::string value;
        std::function<void(simulated_link_settings &)> apply;
    };
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::vector<bad_setting> cases{
        {"latency", "-0.1", [](auto &s) { s.latency = -0.1; }},
        {"latency", "nan", [&](auto &s) { s.latency = nan; }},
        {"jitter", "-1", [](auto &s) { s.jitter = -1; }},
        {"jitter", "nan", [&](auto &s) { s.jitter = nan; }},
        {"reorder_delay", "-0.5", [](auto &s) { s.reorder_delay = -0.5; }},
        {"loss", "1.5", [](auto &s) { s.loss = 1.5; }},
        {"loss", "-0.1", [](auto &s) { s.loss = -0.1; }},
        {"duplication", "nan", [&](auto &s) { s.duplication = nan; }},
        {"duplication", "2", [](auto &s) { s.duplication = 2; }},
        {"reordering", "-1", [](auto &s) { s.reordering = -1; }},
    };
    for (auto &c : cases) {
        simulated_link_settings settings;
        c.apply(settings);
        try {
            simulated_link link(settings);
            ADD_FAILURE() << c.field << " = " << c.value
                          << ": measured no exception, expected std::invalid_argument";
        } catch (const std::invalid_argument &e) {
            std::string what = e.what();
            EXPECT_NE(what.find("simulated_link"), std::string::npos) << "measured \"" << what << "\"";
            EXPECT_NE(what.find(c.field), std::string::npos)
                << "measured \"" << what << "\", expected the field " << c.field;
            EXPECT_NE(what.find(c.value), std::string::npos)
                << "measured \"" << what << "\", expected the value " << c.value;
        }
    }

    simulated_link_settings edges;
    edges.latency = 0;
    edges.loss = 1;
    edges.duplication = 0;
    edges.reordering = 1;
    edges.reorder_delay = 0;
    EXPECT_NO_THROW(simulated_link{edges}) << "boundary values are valid";
}

TEST(simulated_link, send_time_going_backwards_throws) {
    simulated_link link;
    link.send(1.0, payload(0), false);
    EXPECT_NO_THROW(link.send(1.0, payload(1), false)) << "equal times are allowed";
    EXPECT_THROW(link.send(0.5, payload(2), false), std::invalid_argument);
    EXPECT_THROW(link.send(std::numeric_limits<double>::quiet_NaN(), payload(3), false),
                 std::invalid_argument);
    EXPECT_EQ(link.stats().packets_sent, 2u) << "rejected sends are not counted";
}
