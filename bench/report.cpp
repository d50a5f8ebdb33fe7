// Peak memory, the JSON records and the markdown table of edyn-bench.
#include "bench.hpp"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace edyn_bench {

double peak_rss_mb() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line)) {
        if (line.rfind("VmHWM:", 0) == 0) {
            std::istringstream fields(line.substr(6));
            double kb = 0;
            fields >> kb;
            return kb / 1024;
        }
    }
    return 0;
}

void reset_peak_rss() {
    // Linux resets VmHWM to the current resident size when "5" is written here.
    std::ofstream clear_refs("/proc/self/clear_refs");
    clear_refs << "5";
}

namespace {

std::string json_string(const std::string &s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        if (static_cast<unsigned char>(c) < 0x20) continue;
        out += c;
    }
    return out + "\"";
}

std::string number(double value, const char *format = "%.6g") {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, format, value);
    return buffer;
}

const run_result *find_peer(const std::vector<run_result> &results, const run_result &r,
                            const std::string &engine) {
    for (const auto &other : results) {
        if (other.ok && other.engine == engine && other.scene == r.scene && other.bodies == r.bodies) {
            return &other;
        }
    }
    return nullptr;
}

std::string stability_text(const run_result &r) {
    auto cm = number(r.stability * 100, "%.2f");
    if (r.stability_metric == "top_box_displacement_m") return "top box moved " + cm + " cm";
    if (r.stability_metric == "max_penetration_m") return "deepest penetration " + cm + " cm";
    if (r.stability_metric == "bodies_below_terrain") {
        return number(r.stability, "%.0f") + (r.stability == 1 ? " body" : " bodies") + " below the terrain";
    }
    if (r.stability_metric == "max_joint_error_m") {
        return "worst joint error over the run " + number(r.stability * 1000, "%.2f") + " mm";
    }
    return r.stability_metric + " " + number(r.stability);
}

// Exponent k of t ~ n^k between two measurements.
double growth_exponent(double n1, double t1, double n2, double t2) {
    return std::log(t2 / t1) / std::log(n2 / n1);
}

// Between consecutive sizes of each scene and engine, how fast the median time grew with the
// body count next to how fast n log n grows over the same sizes: the issue asks that the piles
// grow no faster than n log n. Only runs timed over the same steps are compared.
std::string growth_table(const std::vector<run_result> &results) {
    std::ostringstream out;
    bool any = false;
    std::vector<std::pair<std::string, std::string>> series;
    for (const auto &r : results) {
        std::pair key{r.scene, r.engine};
        if (r.ok && std::find(series.begin(), series.end(), key) == series.end()) series.push_back(key);
    }
    for (const auto &[scene, engine] : series) {
        std::vector<const run_result *> runs;
        for (const auto &r : results) {
            if (r.ok && r.scene == scene && r.engine == engine && r.bodies > 1 && r.median_ms > 0)
                runs.push_back(&r);
        }
        std::sort(runs.begin(), runs.end(), [](auto *a, auto *b) { return a->bodies < b->bodies; });
        runs.erase(
            std::unique(runs.begin(), runs.end(), [](auto *a, auto *b) { return a->bodies == b->bodies; }),
            runs.end());
        // Each step between sizes, then the whole range when there are more than two.
        std::vector<std::pair<const run_result *, const run_result *>> pairs;
        for (std::size_t i = 1; i < runs.size(); ++i)
            pairs.emplace_back(runs[i - 1], runs[i]);
        if (runs.size() > 2) pairs.emplace_back(runs.front(), runs.back());
        for (auto [first, second] : pairs) {
            const auto &a = *first, &b = *second;
            if (!any) {
                out << "\n| scene | engine | bodies | median ms/step | "
                       "growth exponent | n log n's exponent |\n"
                    << "| --- | --- | --- | --- | ---: | ---: |\n";
                any = true;
            }
            double n1 = a.bodies, n2 = b.bodies;
            out << "| " << scene << " | " << engine << " | " << a.bodies << " → " << b.bodies << " | "
                << number(a.median_ms, "%.3f") << " → " << number(b.median_ms, "%.3f") << " | ";
            if (a.steps == b.steps && a.measured == b.measured) {
                out << number(growth_exponent(n1, a.median_ms, n2, b.median_ms), "%.2f");
            } else {
                out << "not comparable (timed over different steps)";
            }
            out << " | " << number(growth_exponent(n1, n1 * std::log(n1), n2, n2 * std::log(n2)), "%.2f")
                << " |\n";
        }
    }
    return out.str();
}

} // namespace

void write_json(const std::string &path, const std::vector<run_result> &results) {
    std::ofstream out(path);
    if (!out) throw std::runtime_error("edyn-bench: cannot write " + path);
    out << "[\n";
    bool first = true;
    for (const auto &r : results) {
        if (!r.ok) continue;
        out << (first ? "" : ",\n");
        first = false;
        out << "  {\"scene\": " << json_string(r.scene) << ", \"bodies\": " << r.bodies
            << ", \"engine\": " << json_string(r.engine) << ", \"threads\": " << r.threads
            << ", \"steps\": " << r.steps << ", \"measured_steps\": " << r.measured
            << ", \"median_ms\": " << number(r.median_ms) << ", \"p95_ms\": " << number(r.p95_ms)
            << ", \"peak_rss_mb\": " << number(r.peak_rss_mb) << ", \"contacts\": " << r.contacts
            << ", \"stability\": " << number(r.stability)
            << ", \"stability_metric\": " << json_string(r.stability_metric) << "}";
    }
    out << "\n]\n";
    if (!out) throw std::runtime_error("edyn-bench: failed writing " + path);
}

std::string markdown_table(const std::vector<run_result> &results) {
    std::ostringstream out;
    out << "| scene | bodies | engine | steps | median ms/step | p95 ms/step | peak RSS MB | contacts | "
           "stability | edyn/Bullet (median) |\n";
    out << "| --- | ---: | --- | ---: | ---: | ---: | ---: | ---: | --- | ---: |\n";
    for (const auto &r : results) {
        if (!r.ok) {
            out << "| " << r.scene << " | " << r.bodies << " | " << r.engine << " | failed: " << r.error
                << " | | | | | | |\n";
            continue;
        }
        std::string ratio;
        if (r.engine == "edyn") {
            auto *peer = find_peer(results, r, "bullet");
            if (peer && peer->median_ms > 0) ratio = number(r.median_ms / peer->median_ms, "%.2f");
        }
        out << "| " << r.scene << " | " << r.bodies << " | " << r.engine << " | " << r.steps << " | "
            << number(r.median_ms, "%.3f") << " | " << number(r.p95_ms, "%.3f") << " | "
            << number(r.peak_rss_mb, "%.1f") << " | " << r.contacts << " | " << stability_text(r) << " | "
            << ratio << " |\n";
    }
    out << growth_table(results);
    return out.str();
}

} // namespace edyn_bench
