// Peak memory, the JSON records and the markdown table of edyn-bench.
#include "bench.hpp"
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
    if (r.stability_metric == "max_joint_error_m") {
        return "worst joint error over the run " + number(r.stability * 1000, "%.2f") + " mm";
    }
    return r.stability_metric + " " + number(r.stability);
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
    return out.str();
}

} // namespace edyn_bench
