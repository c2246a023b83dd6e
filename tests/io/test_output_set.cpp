// Output paths (links followed, equal files refused) and output sets (published as a whole).

#include "hyst/io/output_set.hpp"

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "../support/temp_folder_test.hpp"
#include "hyst/io/atomic_file.hpp"
#include "hyst/io/output_paths.hpp"

namespace hyst::io {
namespace {

namespace fs = std::filesystem;

class OutputSetTest : public test::TempFolderTest {
 protected:
  static void put(const fs::path& path, const std::string& content) {
    std::ofstream(path, std::ios::binary) << content;
  }
  //! The set folders ".hyst-set.*" in the test folder.
  std::size_t set_folders() const {
    std::size_t count = 0;
    for (const auto& name : entries())
      count += name.rfind(".hyst-set.", 0) == 0 ? 1 : 0;
    return count;
  }
};

TEST_F(OutputSetTest, ResolvesAChainOfLinksToTheFinalTarget) {
  fs::create_directory(dir_ / "real");
  fs::create_symlink("real/target.csv", dir_ / "a");
  fs::create_symlink("a", dir_ / "b");
  const auto target = resolve_output(dir_ / "b");
  EXPECT_EQ(target.path, dir_ / "real/target.csv");
  EXPECT_EQ(target.kind, OutputKind::file);
  write_file_atomically(dir_ / "b", "new");
  EXPECT_TRUE(fs::is_symlink(dir_ / "b"));
  EXPECT_EQ(slurp(dir_ / "real/target.csv"), "new");
}

TEST_F(OutputSetTest, RefusesALinkLoopAFolderAndEqualOutputs) {
  fs::create_symlink("loop2", dir_ / "loop1");
  fs::create_symlink("loop1", dir_ / "loop2");
  EXPECT_HYST_ERROR(resolve_output(dir_ / "loop1"), "too many levels of symbolic links");
  EXPECT_HYST_ERROR(resolve_output(dir_), "it is a folder, not a file");
  put(dir_ / "in.csv", "v\n1\n");
  fs::create_hard_link(dir_ / "in.csv", dir_ / "alias.csv");
  EXPECT_HYST_ERROR(check_outputs({{dir_ / "in.csv", "--input"}}, {{dir_ / "alias.csv", "--out"}}),
                    "alias.csv' is the same file as the input --input '");
  fs::create_directory(dir_ / "x");
  EXPECT_HYST_ERROR(
      check_outputs({}, {{dir_ / "r.txt", "--out"}, {dir_ / "x/../r.txt", "--report"}}),
      "and --report '");
  EXPECT_NO_THROW(check_outputs({{dir_ / "in.csv", "--input"}}, {{dir_ / "out.csv", "--out"}}));
}

TEST_F(OutputSetTest, PublishesEveryNameAtOnceAndDropsNamesTheNewSetLacks) {
  {
    OutputSet set(dir_, {"a.txt", "b.txt"});
    put(set.staged("a.txt"), "a1");
    put(set.staged("b.txt"), "b1");
    EXPECT_FALSE(fs::exists(dir_ / "a.txt"));  // nothing visible before publish()
    set.publish();
  }
  EXPECT_EQ(slurp(dir_ / "a.txt"), "a1");
  EXPECT_EQ(fs::read_symlink(dir_ / "b.txt"), ".hyst-current/b.txt");
  {
    OutputSet set(dir_, {"a.txt"});
    put(set.staged("a.txt"), "a2");
    EXPECT_EQ(slurp(dir_ / "a.txt"), "a1");  // the old set until the switch
    set.publish();
  }
  EXPECT_EQ(slurp(dir_ / "a.txt"), "a2");
  EXPECT_FALSE(fs::exists(fs::symlink_status(dir_ / "b.txt")));
  EXPECT_EQ(set_folders(), 1U);
}

TEST_F(OutputSetTest, AnUnpublishedSetLeavesTheOldOneAndNoStagingFolder) {
  put(dir_ / "a.txt", "plain");  // a plain file of an older run
  {
    OutputSet set(dir_, {"a.txt"});
    put(set.staged("a.txt"), "new");
  }  // e.g. the work failed: never published
  EXPECT_EQ(slurp(dir_ / "a.txt"), "plain");
  EXPECT_EQ(set_folders(), 0U);
  OutputSet set(dir_, {"a.txt"});
  put(set.staged("a.txt"), "new");
  set.publish();
  EXPECT_TRUE(fs::is_symlink(dir_ / "a.txt"));
  EXPECT_EQ(slurp(dir_ / "a.txt"), "new");
}

TEST_F(OutputSetTest, RefusesANameThatIsAFolderOrALinkElsewhere) {
  fs::create_directory(dir_ / "sub");
  EXPECT_HYST_ERROR(OutputSet(dir_, {"sub"}), "it is not a regular file");
  put(dir_ / "elsewhere.txt", "x");
  fs::create_symlink("elsewhere.txt", dir_ / "a.txt");
  EXPECT_HYST_ERROR(OutputSet(dir_, {"a.txt"}), "it is a link elsewhere");
  EXPECT_HYST_ERROR(OutputSet(dir_ / "elsewhere.txt" / "sub", {"a.txt"}),
                    "cannot create the folder '" + (dir_ / "elsewhere.txt" / "sub").string() +
                        "': '" + (dir_ / "elsewhere.txt").string() + "' is not a folder");
}

TEST_F(OutputSetTest, CreatesAMissingFolder) {
  OutputSet set(dir_ / "new" / "results", {"a.txt"});
  put(set.staged("a.txt"), "first\n");
  set.publish();
  EXPECT_EQ(slurp(dir_ / "new" / "results" / "a.txt"), "first\n");
}

}  // namespace
}  // namespace hyst::io
