// Checkpoint files (--checkpoint, --resume, the viewer's checkpoint and
// resume commands): a model's whole state (vv_plugin::save_state) behind a
// short text header that says whose it is, how far it ran and how to check
// it. docs/interpreter.md, "Checkpoints", gives the format:
//
//   vv checkpoint 1
//   program phyllotaxis.vvp
//   program-hash 5c0d...e1 (32 hex digits: vv_plugin::program_hash)
//   step 40
//   seed 3
//   parameter noise=0.25        (one a parameter, for people: the state holds them)
//   state-bytes 81234
//   state-checksum 9f2a...07 (32 hex digits)
//                                (an empty line, then the state's bytes)
//
// Reading checks everything before the model sees a byte: a file that is
// not a checkpoint, one cut short or damaged, and one of another program
// or of an edited one is refused with a message naming the file.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace vvi {

struct checkpoint {
  std::string program;       //!< the .vvp's file name (vv_plugin::program_name)
  std::string program_hash;  //!< vv_plugin::program_hash
  unsigned step = 0;         //!< steps done when it was saved
  std::uint64_t seed = 0;    //!< the run's --seed (the generators' state is in `state`)
  std::vector<std::pair<std::string, std::string>> parameters;  //!< name, value: for people only
  std::string state;         //!< the model's bytes
};

//! The file's bytes.
std::string checkpoint_text(const checkpoint& c);

//! Reads `path`; "" or the error, which names the file.
std::string read_checkpoint(const std::string& path, checkpoint& out);

//! Whether the checkpoint is of this program: "" or why not (naming the file).
std::string check_checkpoint_program(const std::string& path, const checkpoint& c, const std::string& program,
                                     const std::string& program_hash);

}  // namespace vvi
