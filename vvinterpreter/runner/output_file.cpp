#include "runner/output_file.hpp"

#include <vv/io/output_file.hpp>

#include "runner/fault_guard.hpp"

namespace vvi {

std::string write_output(const std::string& path, const std::function<std::string(const std::string&)>& write) {
  std::string error, temporary;
  {
    vv::io::output_file out(path);
    fault_guard::note_writing_in(out.folder_of_temporary());
    if (std::string why = out.make_temporary(); !why.empty()) return path + ": cannot write file: " + why;
    temporary = out.temporary();
    fault_guard::note_writing(temporary, path);
    error = out.in_users_terms(write(temporary));
    if (error.empty()) {
      if (std::string why = out.commit(); !why.empty()) error = path + ": cannot write file: " + why;
    }
  }  // an uncommitted temporary is gone here, before the supervisor hears so
  fault_guard::note_written(temporary);
  return error;
}

}  // namespace vvi
