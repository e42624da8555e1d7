// Before any run of a sweep: the model is compiled once (the runs then
// find it in the cache), and the swept parameters are checked against the
// model's own (their names, and each value against its type and range), so
// a typing error is one message, not a table of failed runs.
#pragma once

#include <string>
#include <vector>

#include "app/options.hpp"
#include "experiment/run_arguments.hpp"
#include "experiment/sweep_plan.hpp"

namespace vvi {

struct checked_model {
  std::string error;    //!< "" or one line: why no run can start
  std::string program;  //!< the program's content hash (experiment/sweep_identity.hpp)
};

//! Compiles the model (o.rebuild: even when the cache holds it; the
//! compiler's report unless o.quiet), then asks the host's --list-params,
//! in a supervised process like the runs', about the parameters.
checked_model check_model(const options& o, const std::string& self, const run_arguments& a,
                          const std::vector<swept_parameter>& swept);

}  // namespace vvi
