// What the machine itself gives to several threads: each kernel does a fixed amount of work on
// one thread, then the same amount on each of N threads at once; the speed-up is N times the
// first time over the second. A physics step cannot scale better than the kernel its hot loops
// resemble: two logical CPUs that share one core's arithmetic units give independent
// floating-point work little speed-up, though they still overlap waits on memory. The step's
// threads also hand data to each other between its passes, at the pace of a cache line's round
// trip between two cores, which a virtual machine's cores may take four times longer over at
// times than at others.

#include "bench.hpp"
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <numeric>
#include <random>
#include <thread>
#include <vector>

namespace edyn_bench {
namespace {

// Multiply-adds in eight independent chains: bound by the arithmetic units' throughput.
double arithmetic(std::uint64_t iterations, float seed) {
    float chain[8];
    for (int k = 0; k < 8; ++k)
        chain[k] = seed + float(k);
    for (std::uint64_t i = 0; i < iterations; ++i) {
        for (auto &value : chain)
            value = value * 0.9999999f + 0.5f;
    }
    return std::accumulate(chain, chain + 8, 0.0);
}

// A walk through one random cycle over the whole table: each load waits for the one before, so
// it is bound by memory latency.
double memory_latency(const std::vector<std::uint32_t> &next, std::uint64_t loads) {
    std::uint32_t at = 0;
    for (std::uint64_t i = 0; i < loads; ++i)
        at = next[at];
    return at;
}

// Sums of the whole table, again and again: bound by memory bandwidth.
double memory_bandwidth(const std::vector<std::uint32_t> &table, unsigned passes) {
    std::uint64_t sum = 0;
    for (unsigned pass = 0; pass < passes; ++pass)
        sum += std::accumulate(table.begin(), table.end(), std::uint64_t(0));
    return double(sum);
}

// One cycle through every slot (Sattolo's shuffle), far larger than any cache.
std::vector<std::uint32_t> random_cycle(std::size_t size, std::uint32_t seed) {
    std::vector<std::uint32_t> next(size);
    std::iota(next.begin(), next.end(), 0u);
    std::mt19937 rng(seed);
    for (auto i = size - 1; i > 0; --i) {
        std::uniform_int_distribution<std::size_t> pick(0, i - 1);
        std::swap(next[i], next[pick(rng)]);
    }
    return next;
}

// Waits until `counter` holds `turn`: spins, then lets the other thread run, so that two threads
// on one core still take their turns.
void wait_for(const std::atomic<std::uint32_t> &counter, std::uint32_t turn) {
    for (unsigned spins = 0; counter.load(std::memory_order_acquire) != turn; ++spins) {
        if (spins >= 10000) std::this_thread::yield();
    }
}

// Nanoseconds for a cache line to go from one thread to another and back: the threads take turns
// to write a counter, each waiting for the other's write.
double round_trip_ns() {
    constexpr std::uint32_t turns = 200'000;
    alignas(64) std::atomic<std::uint32_t> counter{0};
    auto start = std::chrono::steady_clock::now();
    std::thread other([&] {
        for (std::uint32_t turn = 1; turn < 2 * turns; turn += 2) {
            wait_for(counter, turn);
            counter.store(turn + 1, std::memory_order_release);
        }
    });
    for (std::uint32_t turn = 0; turn < 2 * turns; turn += 2) {
        wait_for(counter, turn);
        counter.store(turn + 1, std::memory_order_release);
    }
    other.join();
    return std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count() / turns;
}

// Seconds for every thread to run kernel(thread index) once, all started together.
template<typename Kernel>
double seconds_on(unsigned threads, const Kernel &kernel) {
    std::vector<double> sinks(threads);
    auto start = std::chrono::steady_clock::now();
    std::vector<std::thread> others;
    for (unsigned t = 1; t < threads; ++t)
        others.emplace_back([&, t] { sinks[t] = kernel(t); });
    sinks[0] = kernel(0);
    for (auto &thread : others)
        thread.join();
    auto seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // The results are printed nowhere, but read: the kernels cannot be dropped as dead code.
    volatile double keep = std::accumulate(sinks.begin(), sinks.end(), 0.0);
    (void)keep;
    return seconds;
}

template<typename Kernel>
double speed_up(unsigned threads, const Kernel &kernel) {
    auto alone = seconds_on(1, kernel);
    return threads * alone / seconds_on(threads, kernel);
}

} // namespace

std::vector<ceiling_row> machine_ceiling(const std::vector<unsigned> &thread_counts) {
    unsigned most = 1;
    for (auto threads : thread_counts)
        most = std::max(most, threads);
    // 64 MiB a thread (1 GiB for 16), each its own table, so that threads share no line.
    auto slots = std::size_t(16) << 20;
    std::vector<std::vector<std::uint32_t>> tables;
    for (unsigned t = 0; t < most; ++t)
        tables.push_back(random_cycle(slots, t + 1));
    auto iterations = std::uint64_t(200'000'000);
    auto loads = std::uint64_t(4'000'000);

    std::vector<ceiling_row> rows;
    for (auto threads : thread_counts) {
        ceiling_row row;
        row.threads = threads;
        row.arithmetic = speed_up(threads, [&](unsigned t) { return arithmetic(iterations, float(t)); });
        row.memory_latency = speed_up(threads, [&](unsigned t) { return memory_latency(tables[t], loads); });
        row.memory_bandwidth = speed_up(threads, [&](unsigned t) { return memory_bandwidth(tables[t], 16); });
        row.round_trip_ns = round_trip_ns();
        rows.push_back(row);
    }
    return rows;
}

std::string ceiling_table(const std::vector<ceiling_row> &rows) {
    std::string table = "| threads | independent arithmetic | memory latency | memory bandwidth | "
                        "round trip between two threads (ns) |\n"
                        "| ---: | ---: | ---: | ---: | ---: |\n";
    char line[128];
    for (auto &row : rows) {
        std::snprintf(line, sizeof(line), "| %u | %.2f | %.2f | %.2f | ", row.threads, row.arithmetic,
                      row.memory_latency, row.memory_bandwidth);
        table += line;
        std::snprintf(line, sizeof(line), "%.0f |\n", row.round_trip_ns);
        table += line;
    }
    return table;
}

} // namespace edyn_bench
