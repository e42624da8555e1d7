// How a viewer that died comes back: from the last state record it sent
// and the way it ended, the record the next window starts from. A crash
// in a new build on its way in (loading, start, its replay) brings the
// last good model back and keeps the new build from loading again until
// it changes; a crash while the log was replayed stops the replay at that
// event; a crash in a render block keeps that build's render blocks off.
// Nothing is run twice: the command that crashed is not in the log.
#pragma once

#include <string>

#include "app/options.hpp"
#include "control/state_record.hpp"
#include "runner/supervisor.hpp"

namespace vvi {

struct restart {
  state_record record;  //!< what the next window starts from
  std::string report;   //!< what to say on standard error (lines ending in '\n')
};

//! Whether the window process ended because its model called exit() (or
//! _exit) inside one of its blocks, not because the viewer quit or asked
//! for a restart.
bool ended_by_model_exit(const child_end& end);

//! `last`: the record the dead window sent last; `end`: how it ended (a
//! crash, a time-out, its exit asking for a restart after a Stop, or its
//! model's exit()).
restart restart_after(const options& o, const state_record& last, const child_end& end);

}  // namespace vvi
