#include "control/model_facts.hpp"

#include "runner/parameters.hpp"
#include "runner/session.hpp"

namespace vvi {

model_facts read_facts(const session* model, const std::vector<std::string>& file_objects) {
  model_facts f;
  if (!model) return f;
  f.loaded = true;
  f.steps = model->steps_done();
  f.last_step_ms = model->last_step_ms();
  vv_run_settings run = model->run_settings();
  f.run_steps = run.steps;
  f.delay_msec = run.delay_msec;
  f.can_animate = !run.no_animate;
  f.record_frame = run.record_frame != 0;
  for (const vv_mesh_entry* m : model->meshes()) f.meshes.emplace_back(m->name, m->vertex_count());
  for (const vv_param_entry* e : parameters_of(*model))
    f.parameters.push_back({e->name, e->type, parameter_text(*e), parameter_number(*e), e->has_range != 0, e->lo,
                            e->hi, e->line});
  // Copied: the series' arrays are the model's, valid only until its code runs again.
  for (const vv_plot_series& series : model->plots()) {
    plot_view v;
    v.name = series.name;
    v.values.assign(series.values, series.values + series.count);
    if (series.count) {
      v.first_step = series.steps[0], v.last_step = series.steps[series.count - 1];
      v.last = series.values[series.count - 1];
    }
    f.plots.push_back(std::move(v));
  }
  for (const vv_action_entry* a : model->actions()) f.actions.push_back({a->name, a->key, a->line});
  f.has_pick = model->model().pick != nullptr;
  f.file_objects = file_objects;
  return f;
}

}  // namespace vvi
