// edyn-netbench's markdown tables and JSON records.
#include "netbench.hpp"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace edyn_netbench {

void add_metric(results &out, const char *scenario, std::string name, double value, std::string unit,
                std::string target, int met) {
    auto m = metric{};
    m.scenario = scenario;
    m.name = std::move(name);
    m.value = value;
    m.unit = std::move(unit);
    m.target = std::move(target);
    m.met = met;
    out.metrics.push_back(std::move(m));
}

double percentile(std::vector<double> values, double p) {
    if (values.empty()) return 0;
    std::sort(values.begin(), values.end());
    auto rank = std::clamp(p, 0.0, 1.0) * double(values.size() - 1);
    auto low = std::size_t(std::floor(rank));
    auto high = std::min(low + 1, values.size() - 1);
    return values[low] + (values[high] - values[low]) * (rank - double(low));
}

double median(std::vector<double> values) { return percentile(std::move(values), 0.5); }

namespace {

std::string number(double value) {
    char buffer[64];
    auto magnitude = std::abs(value);
    const char *format = magnitude >= 100  ? "%.0f"
                         : magnitude >= 10 ? "%.1f"
                         : magnitude >= 1  ? "%.2f"
                                           : "%.3f";
    std::snprintf(buffer, sizeof buffer, format, value);
    return buffer;
}

std::string json_string(const std::string &s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        if (static_cast<unsigned char>(c) < 0x20) continue;
        out += c;
    }
    return out + "\"";
}

std::string json_number(double value) {
    if (!std::isfinite(value)) return "null";
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.6g", value);
    return buffer;
}

const char *met_text(int met) { return met < 0 ? "" : met ? "yes" : "**no**"; }

} // namespace

std::string markdown_report(const results &r) {
    std::ostringstream out;
    out << "| scenario | figure | value | unit | target | met |\n";
    out << "| --- | --- | ---: | --- | --- | --- |\n";
    for (auto &m : r.metrics) {
        auto value = number(m.value);
        if (!m.runs.empty()) {
            auto [lo, hi] = std::minmax_element(m.runs.begin(), m.runs.end());
            value += " (" + number(*lo) + "–" + number(*hi) + ")";
        }
        out << "| " << m.scenario << " | " << m.name << " | " << value << " | " << m.unit << " | " << m.target
            << " | " << met_text(m.met) << " |\n";
    }
    if (std::any_of(r.metrics.begin(), r.metrics.end(), [](auto &m) { return !m.runs.empty(); }))
        out << "\nWith several runs: the median of the runs, their range in brackets.\n";
    if (!r.breakdown.empty()) {
        out << "\n| scenario | phase | bytes of | count | bytes | bytes/s | share |\n";
        out << "| --- | --- | --- | ---: | ---: | ---: | ---: |\n";
        for (auto &b : r.breakdown) {
            out << "| " << b.scenario << " | " << b.phase << " | " << b.part << " | ";
            if (!b.count_of.empty()) out << b.count << " " << b.count_of;
            out << " | " << b.bytes << " | " << number(b.bytes_per_second) << " | " << number(b.share * 100)
                << "% |\n";
        }
    }
    if (!r.notes.empty()) {
        out << "\n";
        for (auto &n : r.notes)
            out << "- " << n << "\n";
    }
    return out.str();
}

void write_json(const std::string &path, const results &r) {
    std::ofstream out(path);
    if (!out) throw std::runtime_error("edyn-netbench: cannot write " + path);
    out << "{\n  \"metrics\": [";
    for (std::size_t i = 0; i < r.metrics.size(); ++i) {
        auto &m = r.metrics[i];
        out << (i ? ",\n    " : "\n    ") << "{\"scenario\": " << json_string(m.scenario)
            << ", \"name\": " << json_string(m.name) << ", \"value\": " << json_number(m.value)
            << ", \"unit\": " << json_string(m.unit);
        if (!m.target.empty())
            out << ", \"target\": " << json_string(m.target) << ", \"met\": " << (m.met ? "true" : "false");
        if (!m.runs.empty()) {
            out << ", \"runs\": [";
            for (std::size_t k = 0; k < m.runs.size(); ++k)
                out << (k ? ", " : "") << json_number(m.runs[k]);
            out << "]";
        }
        out << "}";
    }
    out << "\n  ],\n  \"breakdown\": [";
    for (std::size_t i = 0; i < r.breakdown.size(); ++i) {
        auto &b = r.breakdown[i];
        out << (i ? ",\n    " : "\n    ") << "{\"scenario\": " << json_string(b.scenario)
            << ", \"phase\": " << json_string(b.phase) << ", \"part\": " << json_string(b.part)
            << ", \"count\": " << b.count << ", \"count_of\": " << json_string(b.count_of)
            << ", \"bytes\": " << b.bytes << ", \"bytes_per_second\": " << json_number(b.bytes_per_second)
            << ", \"share\": " << json_number(b.share) << "}";
    }
    out << "\n  ],\n  \"notes\": [";
    for (std::size_t i = 0; i < r.notes.size(); ++i)
        out << (i ? ",\n    " : "\n    ") << json_string(r.notes[i]);
    out << "\n  ]\n}\n";
    if (!out) throw std::runtime_error("edyn-netbench: failed writing " + path);
}

} // namespace edyn_netbench
