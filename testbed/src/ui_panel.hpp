// The Dear ImGui panel: the samples by category, pause/step/reset/slow motion, the world's
// settings, what is drawn, and where the time goes (physics vs drawing, a plot of ms per step).
#ifndef EDYN_TESTBED_UI_PANEL_HPP
#define EDYN_TESTBED_UI_PANEL_HPP

namespace testbed {

class app;

void draw_panel(app &a);

} // namespace testbed

#endif // EDYN_TESTBED_UI_PANEL_HPP
