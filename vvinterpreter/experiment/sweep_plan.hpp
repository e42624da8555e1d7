// A sweep's plan: every combination of the swept parameters' values and of
// the seeds, in a fixed order, numbered from 1. The first --sweep varies
// slowest and the seed fastest, so a combination's replicates are
// neighbours. The plan is the same on every machine and for any --jobs,
// which is what makes the tables byte-identical and shards mergeable.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace vvi {

struct swept_parameter {
  std::string name;
  std::string typed;                //!< the option's value as typed ("rate=0:1:5")
  std::vector<std::string> values;  //!< as given (a list), or the range's values written exactly
};

//! Reads "NAME=V1,V2,..." or "NAME=LO:HI:COUNT" (COUNT values from LO to
//! HI, evenly spaced; both ends included). Throws std::invalid_argument
//! naming the option: no name, an empty value, COUNT 0, HI below LO, a
//! value listed twice.
swept_parameter parse_sweep(const std::string& typed);

struct planned_run {
  unsigned number = 0;             //!< 1, 2, ...
  std::uint64_t seed = 0;
  std::vector<std::string> values; //!< one per swept parameter, in the plan's order
};

class sweep_plan {
 public:
  //! seeds: 1..K when K > 0, else the single seed `fixed_seed` (--seed).
  //! Throws std::invalid_argument for a parameter swept twice.
  sweep_plan(std::vector<swept_parameter> parameters, unsigned seeds, std::uint64_t fixed_seed);

  const std::vector<swept_parameter>& parameters() const { return parameters_; }
  const std::vector<std::uint64_t>& seeds() const { return seeds_; }
  std::size_t size() const;
  //! Run `number` (1..size()).
  planned_run run(unsigned number) const;
  //! The runs of shard i of n (--shard I/N): every n-th run from run i.
  std::vector<unsigned> shard(unsigned i, unsigned n) const;

  //! "run-0007": the run's folder; the number is at least four digits
  //! wide, wider when the plan has more runs.
  std::string folder(unsigned number) const;
  //! "rate=0.5 seed=2": the run in words, for messages.
  std::string describe(const planned_run& r) const;

 private:
  std::vector<swept_parameter> parameters_;
  std::vector<std::uint64_t> seeds_;
};

}  // namespace vvi
