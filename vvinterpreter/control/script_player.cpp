#include "control/script_player.hpp"

#include "control/model_controller.hpp"

namespace vvi {

void script_player::feed(model_controller& c) {
  while (position_ < commands_.size()) {
    const command& next = commands_[position_];
    if (next.kind == command::stop && c.busy()) {
      if (c.job_seconds() < long_job_seconds || !c.view_caught_up()) return;
    } else {
      bool beside = next.kind == command::wait || next.kind == command::window_screenshot;
      if (!c.idle() && !(beside && c.only_a_job_runs())) return;
    }
    ++position_;
    c.set_script_position(position_);
    c.submit(next);
  }
}

}  // namespace vvi
