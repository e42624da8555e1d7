// The file objects' registries (model/file_registry.hpp): an object joins
// the registry of the model whose code runs while it is made, for as long
// as it exists (its copies too); an object made outside any model joins
// none; the host lists a model's files and rereads each object once.
#include <model/file_registry.hpp>
#include <model/registered_file.hpp>

#include <util/contour.hpp>
#include <util/function.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "test_files.hpp"

namespace {

using test_files::write_scratch;
using vv::file_kind;
using vv::model::file_registry;
using vv::model::registry_scope;

bool registered(const file_registry& r, const vv::file_object* object, file_kind kind) {
  const auto& list = r.objects(kind);
  return std::count(list.begin(), list.end(), object) == 1;
}

// Counts its rereads; throws when told to.
struct counting_contents {};
class counting : public vv::model::registered_file<counting, file_kind::functions, counting_contents> {
 public:
  counting() = default;
  static counting_contents read(const std::string&) { return {}; }
  void reread() override {
    ++rereads;
    if (fail) throw std::runtime_error(name + ": broken");
  }
  std::string name;
  int rereads = 0;
  bool fail = false;
};

// A program's own file object, not registered.
struct unregistered : vv::file_object {
  void reread() override { ++rereads; }
  int rereads = 0;
};

const std::string line = "fver 1 1\nname: l\nsamples: 10\nflip: off\npoints: 4\n0 0\n0.3 0.3\n0.6 0.6\n1 1\n";

// What reread() takes besides the registered objects: none.
const std::vector<vv::file_object*> none;
const std::array<const std::vector<vv::file_object*>*, vv::file_kind_count> no_lists = {&none, &none, &none, &none};

TEST(FileRegistry, ObjectsJoinTheModelTheyAreMadeInWhileTheyExist) {
  file_registry model;
  {
    registry_scope running(model);
    util::Function f(write_scratch("reg.func", line));
    EXPECT_TRUE(registered(model, &f, file_kind::functions));
    EXPECT_FALSE(registered(model, &f, file_kind::contours));

    util::Function copy(f);
    EXPECT_TRUE(registered(model, &copy, file_kind::functions));
    EXPECT_EQ(copy.path(), f.path());

    util::Function moved(std::move(copy));  // a move copies: both keep file and values
    EXPECT_TRUE(registered(model, &moved, file_kind::functions));
    EXPECT_TRUE(registered(model, &copy, file_kind::functions));
    EXPECT_EQ(copy.path(), f.path());
    EXPECT_DOUBLE_EQ(copy(0.5), 0.5);
    EXPECT_DOUBLE_EQ(moved(0.5), 0.5);
    EXPECT_EQ(model.size(), 3u);

    util::Function empty;
    empty = f;  // assignment keeps the one registration
    EXPECT_TRUE(registered(model, &empty, file_kind::functions));
    EXPECT_EQ(empty.path(), f.path());
    EXPECT_DOUBLE_EQ(empty(0.5), 0.5);
    EXPECT_EQ(model.size(), 4u);
  }
  EXPECT_EQ(model.size(), 0u);
}

TEST(FileRegistry, AnObjectMadeOutsideAnyModelJoinsNone) {
  file_registry model;
  {
    registry_scope running(model);
  }
  EXPECT_EQ(vv::model::running_registry(), nullptr);
  util::Function f(write_scratch("outside.func", line));
  EXPECT_EQ(model.size(), 0u);
  EXPECT_DOUBLE_EQ(f(0.5), 0.5);  // and it works as well
}

TEST(FileRegistry, TwoModelsKeepTheirObjectsApart) {
  file_registry a, b;
  const std::string path = write_scratch("apart.func", line);
  registry_scope in_a(a);
  util::Function of_a(path);
  {
    registry_scope in_b(b);
    util::Function of_b(path);
    util::Function copy_of_a(of_a);  // a copy belongs where its source does
    EXPECT_TRUE(registered(a, &of_a, file_kind::functions));
    EXPECT_TRUE(registered(a, &copy_of_a, file_kind::functions));
    EXPECT_TRUE(registered(b, &of_b, file_kind::functions));
    EXPECT_EQ(a.size(), 2u);
    EXPECT_EQ(b.size(), 1u);
  }
  EXPECT_EQ(vv::model::running_registry(), &a);  // the scope ends where it began
  EXPECT_EQ(a.size(), 1u);
  EXPECT_EQ(b.size(), 0u);
}

TEST(FileRegistry, RelativeNamesResolveAgainstTheModelsFolder) {
  write_scratch("beside.func", line);
  file_registry model;
  model.set_base_dir(test_files::scratch_dir() + "sub/..");
  registry_scope running(model);
  util::Function f("beside.func");
  EXPECT_EQ(f.path(), test_files::scratch_dir() + "beside.func");
  EXPECT_DOUBLE_EQ(f(0.5), 0.5);
}

TEST(FileRegistry, AFailedConstructionLeavesNothingRegistered) {
  file_registry model;
  registry_scope running(model);
  EXPECT_THROW(util::Function(test_files::scratch_dir() + "absent.func"), vv::error);
  EXPECT_EQ(model.size(), 0u);
}

TEST(FileRegistry, PathsListsEachFileOnce) {
  const std::string fpath = write_scratch("listed.func", line);
  const std::string cpath = write_scratch("listed.con", "4 2 closed\n1 1\n1 -1\n-1 -1\n-1 1\n");
  file_registry model;
  registry_scope running(model);
  util::Contour c(cpath);  // made first, listed after the functions
  util::Function f(fpath), again(fpath);
  util::Function nothing;  // no file: not listed
  EXPECT_EQ(model.paths(), (std::vector<std::string>{fpath, cpath}));
}

TEST(FileRegistry, RereadReachesEachObjectOnce) {
  file_registry model;
  registry_scope running(model);
  counting registered_and_listed, only_registered;
  unregistered listed;
  std::vector<vv::file_object*> functions = {&registered_and_listed, &registered_and_listed};
  std::vector<vv::file_object*> palettes = {&registered_and_listed};  // even under another kind
  std::vector<vv::file_object*> materials = {&listed};
  model.reread({&materials, &palettes, &functions, &none});
  EXPECT_EQ(registered_and_listed.rereads, 1);
  EXPECT_EQ(only_registered.rereads, 1);
  EXPECT_EQ(listed.rereads, 1);
  model.reread({&materials, &palettes, &functions, &none});
  EXPECT_EQ(registered_and_listed.rereads, 2);
  EXPECT_EQ(only_registered.rereads, 2);
  EXPECT_EQ(listed.rereads, 2);
}

TEST(FileRegistry, AFailureDoesNotStopTheOthers) {
  file_registry model;
  registry_scope running(model);
  counting first, second, third;
  first.name = "first", second.name = "second", third.name = "third";
  first.fail = true;
  second.fail = true;
  try {
    model.reread(no_lists);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "first: broken");  // the first failure
  }
  EXPECT_EQ(first.rereads, 1);
  EXPECT_EQ(second.rereads, 1);
  EXPECT_EQ(third.rereads, 1);
}

TEST(FileRegistry, RereadReachesARealFunction) {
  const std::string path = write_scratch("host.func", line);
  file_registry model;
  registry_scope running(model);
  util::Function f(path);
  EXPECT_DOUBLE_EQ(f(0.5), 0.5);
  write_scratch("host.func", "fver 1 1\nname: l\nsamples: 10\nflip: off\npoints: 4\n0 1\n0.3 1\n0.6 1\n1 1\n");
  model.reread(no_lists);
  EXPECT_DOUBLE_EQ(f(0.5), 1.0);
}

}  // namespace
