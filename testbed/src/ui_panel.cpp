#include "ui_panel.hpp"
#include "app.hpp"
#include <algorithm>
#include <imgui.h>
#include <map>
#include <vector>

namespace testbed {

namespace {

void sample_list(app &a) {
    // Categories in the order they first appear.
    std::vector<std::string> categories;
    for (auto &s : all_samples())
        if (std::find(categories.begin(), categories.end(), s.category) == categories.end())
            categories.push_back(s.category);
    for (auto &category : categories) {
        if (!ImGui::TreeNodeEx(category.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) continue;
        for (auto &s : all_samples()) {
            if (s.category != category) continue;
            if (ImGui::Selectable(s.name.c_str(), &s == a.current_sample())) a.requested = &s;
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", s.description.c_str());
        }
        ImGui::TreePop();
    }
}

void time_controls(app &a) {
    ImGui::Checkbox("Pause (P)", &a.ctl.paused);
    ImGui::SameLine();
    if (ImGui::Button("Step (S)")) a.ctl.step_once = true;
    ImGui::SameLine();
    if (ImGui::Button("Reset (R)")) a.ctl.reset = true;
    ImGui::Checkbox("Slow motion (M)", &a.ctl.slow_motion);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(80);
    ImGui::SliderFloat("##factor", &a.ctl.slow_factor, 0.05f, 1.0f, "x%.2f");
}

void settings_controls(app &a) {
    auto &s = a.settings;
    bool changed = false;
    changed |= ImGui::SliderInt("Sub-steps", &s.substeps, 1, 16);
    changed |= ImGui::SliderInt("Relax iterations", &s.relax_iterations, 0, 8);
    changed |= ImGui::SliderInt("Position iterations", &s.position_iterations, 0, 8);
    changed |= ImGui::SliderInt("Restitution iterations", &s.restitution_iterations, 0, 16);
    changed |= ImGui::SliderFloat("Gravity y", &s.gravity_y, -30.0f, 30.0f, "%.1f m/s2");
    if (changed) a.apply_settings();
    static const char *modes[] = {"sequential", "sequential multithreaded", "asynchronous"};
    int mode = int(s.mode);
    // A new execution mode needs a new attach: the sample restarts in it.
    if (ImGui::Combo("Execution", &mode, modes, 3)) {
        s.mode = edyn::execution_mode(mode);
        a.ctl.reset = true;
    }
}

void stats_view(app &a) {
    auto &st = a.stats;
    double fps = st.frame_ms > 0 ? 1000.0 / st.frame_ms : 0;
    ImGui::Text("Frame %.1f ms (%.0f fps)", st.frame_ms, fps);
    ImGui::Text("Physics %.2f ms (%u steps, %.2f ms each)", st.physics_ms, st.steps, st.ms_per_step);
    ImGui::Text("Drawing %.2f ms (lists %.2f ms, %d calls)", st.draw_ms, st.draw_lists_ms, st.draw_calls);
    if (a.settings.mode == edyn::execution_mode::asynchronous) {
        ImGui::TextDisabled("(asynchronous: the steps run on the worker thread)");
    }
    ImGui::Text("Bodies %zu, manifolds %zu", st.bodies, st.manifolds);
    ImGui::Text("Contact points %zu, islands %zu (%zu asleep)", st.contact_points, st.islands,
                st.sleeping_islands);
    if (st.pages > 0) {
        if (a.settings.mode == edyn::execution_mode::asynchronous) {
            ImGui::Text("Mesh pages: %zu (owned by the worker: not drawn)", st.pages);
        } else {
            ImGui::Text("Mesh pages loaded: %zu of %zu", st.loaded_pages, st.pages);
        }
    }
    std::vector<float> history(st.step_history.begin(), st.step_history.end());
    float top = 1;
    for (auto v : history)
        top = std::max(top, v);
    char label[32];
    std::snprintf(label, sizeof label, "max %.1f ms", double(top));
    ImGui::PlotLines("##ms", history.data(), int(history.size()), 0, label, 0, top * 1.1f,
                     ImVec2(ImGui::GetContentRegionAvail().x, 60));
    ImGui::TextDisabled("ms per step, last %zu steps", history.size());
}

void draw_options(app &a) {
    auto &d = a.ctl.debug;
    ImGui::Checkbox("Contacts (C)", &d.contacts);
    ImGui::SameLine();
    ImGui::Checkbox("Normals (N)", &d.normals);
    ImGui::Checkbox("AABBs (A)", &d.aabbs);
    ImGui::SameLine();
    ImGui::Checkbox("Islands (I)", &d.islands);
    ImGui::Checkbox("Grey sleeping bodies", &d.grey_sleeping);
    ImGui::Checkbox("Ray from cursor (Y)", &a.ctl.show_ray);
    auto &hit = a.probe.last;
    if (a.ctl.show_ray && hit.body != edyn::null) {
        ImGui::Text("hit body %u at (%.2f %.2f %.2f)", unsigned(edyn::to_index(hit.body)),
                    double(hit.point.x), double(hit.point.y), double(hit.point.z));
        ImGui::Text("normal (%.2f %.2f %.2f)", double(hit.normal.x), double(hit.normal.y),
                    double(hit.normal.z));
    }
}

} // namespace

void draw_panel(app &a) {
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(340, 0), ImGuiCond_FirstUseEver);
    ImGui::Begin("edyn testbed (Tab hides)");
    if (auto *s = a.current_sample()) {
        ImGui::TextWrapped("%s: %s", s->name.c_str(), s->description.c_str());
        if (!a.current_state().help.empty()) ImGui::TextWrapped("%s", a.current_state().help.c_str());
    }
    if (ImGui::CollapsingHeader("Simulation", ImGuiTreeNodeFlags_DefaultOpen)) time_controls(a);
    if (ImGui::CollapsingHeader("Performance", ImGuiTreeNodeFlags_DefaultOpen)) stats_view(a);
    if (ImGui::CollapsingHeader("Settings")) settings_controls(a);
    if (ImGui::CollapsingHeader("Draw", ImGuiTreeNodeFlags_DefaultOpen)) draw_options(a);
    if (ImGui::CollapsingHeader("Controls")) {
        ImGui::TextWrapped("Left drag: pull a body. Right drag: orbit. Middle drag or Shift+right: pan. "
                           "Wheel: zoom. B: shoot a ball. P pause, S step, R reset, M slow motion, "
                           "Tab panel, Esc quit.");
    }
    ImGui::End();

    // The samples in a window of their own at the right edge.
    auto &io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - 8, 8), ImGuiCond_FirstUseEver, ImVec2(1, 0));
    ImGui::SetNextWindowSize(ImVec2(180, 0), ImGuiCond_FirstUseEver);
    ImGui::Begin("Samples");
    sample_list(a);
    ImGui::End();
}

} // namespace testbed
