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
  const vv::proxy& p = model->proxy();
  f.run_steps = p.steps;
  f.delay_msec = p.delay_msec;
  f.can_animate = !p.no_animate;
  f.record_frame = p.record_frame;
  for (const vv_mesh_entry* m : model->meshes()) f.meshes.emplace_back(m->name, m->vertex_count());
  for (const vv_param_entry* e : parameters_of(*model))
    f.parameters.push_back({e->name, e->type, parameter_text(*e), parameter_number(*e), e->has_range != 0, e->lo,
                            e->hi, e->line});
  for (const vv::plot_series& series : p.plots) {
    plot_view v;
    v.name = series.name;
    v.values.assign(series.values.begin(), series.values.end());
    if (!series.steps.empty()) v.first_step = series.steps.front(), v.last_step = series.steps.back();
    if (!series.values.empty()) v.last = series.values.back();
    f.plots.push_back(std::move(v));
  }
  f.file_objects = file_objects;
  return f;
}

}  // namespace vvi
