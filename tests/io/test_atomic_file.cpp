#include "hyst/io/atomic_file.hpp"

#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "../support/expect_error.hpp"
#include "../support/temp_folder_test.hpp"

namespace hyst::io {
namespace {

namespace fs = std::filesystem;

class AtomicFileTest : public test::TempFolderTest {
 protected:
  static void put(const fs::path& path, const std::string& content) {
    std::ofstream(path, std::ios::binary) << content;
  }
};

TEST_F(AtomicFileTest, CreatesTheFileWithTheContentAndLeavesNoTemporary) {
  const fs::path target = dir_ / "out.csv";
  write_file_atomically(target, "t,v\n0,1\n");
  EXPECT_EQ(slurp(target), "t,v\n0,1\n");
  EXPECT_EQ(entries(), std::vector<std::string>{"out.csv"});
}

TEST_F(AtomicFileTest, ReplacesAnExistingFileAndKeepsItsPermissions) {
  const fs::path target = dir_ / "out.csv";
  put(target, "old content that is longer than the new one\n");
  ASSERT_EQ(::chmod(target.c_str(), 0640), 0);
  write_file_atomically(target, "new\n");
  EXPECT_EQ(slurp(target), "new\n");
  struct stat status {};
  ASSERT_EQ(::stat(target.c_str(), &status), 0);
  EXPECT_EQ(status.st_mode & 07777, 0640u);
  EXPECT_EQ(entries(), std::vector<std::string>{"out.csv"});
}

TEST_F(AtomicFileTest, EmptyAndBinaryContentRoundTripThroughReadFile) {
  const fs::path empty = dir_ / "empty";
  write_file_atomically(empty, "");
  EXPECT_TRUE(fs::exists(empty));
  EXPECT_EQ(read_file(empty), "");

  std::string binary(3 << 20, '\0');  // 3 MiB, larger than one read buffer, with NUL bytes
  for (std::size_t i = 0; i < binary.size(); ++i)
    binary[i] = static_cast<char>((i * 7919) % 251);
  const fs::path big = dir_ / "big.bin";
  write_file_atomically(big, binary);
  EXPECT_EQ(read_file(big), binary);
  EXPECT_EQ(entries(), (std::vector<std::string>{"big.bin", "empty"}));
}

TEST_F(AtomicFileTest, RepeatedAndConcurrentWritesLeaveOneCompleteFile) {
  const fs::path target = dir_ / "shared.txt";
  std::vector<std::string> contents;
  for (int i = 0; i < 4; ++i)
    contents.push_back(std::string(10000 + i, static_cast<char>('a' + i)));
  std::vector<std::thread> writers;
  for (int i = 0; i < 4; ++i) {
    writers.emplace_back([&, i] {
      for (int n = 0; n < 25; ++n)
        write_file_atomically(target, contents[i]);
    });
  }
  for (auto& writer : writers)
    writer.join();
  EXPECT_NE(std::find(contents.begin(), contents.end(), read_file(target)), contents.end());
  EXPECT_EQ(entries(), std::vector<std::string>{"shared.txt"});
}

TEST_F(AtomicFileTest, RelativePathInTheCurrentFolder) {
  const fs::path previous = fs::current_path();
  fs::current_path(dir_);
  write_file_atomically("relative.txt", "here\n");
  const std::string content = read_file("relative.txt");
  fs::current_path(previous);
  EXPECT_EQ(content, "here\n");
  EXPECT_EQ(entries(), std::vector<std::string>{"relative.txt"});
}

TEST_F(AtomicFileTest, MissingFoldersAreCreated) {
  const fs::path target = dir_ / "new" / "sub" / "out.csv";
  write_file_atomically(target, "x\n");
  EXPECT_EQ(slurp(target), "x\n");
  EXPECT_EQ(entries(), std::vector<std::string>{"new"});
}

TEST_F(AtomicFileTest, ParentThatIsARegularFileThrowsAndLeavesThatFileAlone) {
  const fs::path existing = dir_ / "data.csv";
  put(existing, "t,v\n0,1\n");
  const fs::path target = existing / "out.csv";
  EXPECT_HYST_ERROR(
      write_file_atomically(target, "new"),
      fmt::format("cannot write '{}': '{}' is not a folder", target.string(), existing.string()));
  EXPECT_EQ(slurp(existing), "t,v\n0,1\n");
  EXPECT_EQ(entries(), std::vector<std::string>{"data.csv"});
}

// A failure in the middle of writing (here: the process's file size limit, which also holds for
// root) must leave the existing target untouched and remove the temporary file.
TEST_F(AtomicFileTest, FailedWriteKeepsTheExistingFileIntact) {
  const fs::path target = dir_ / "model.csv";
  put(target, "the old, complete content\n");

  const auto previous_handler = std::signal(SIGXFSZ, SIG_IGN);  // get EFBIG instead of a signal
  rlimit previous_limit{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &previous_limit), 0);
  rlimit small = previous_limit;
  small.rlim_cur = 4096;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  std::string message;
  try {
    write_file_atomically(target, std::string(100000, 'x'));
  } catch (const Error& error) {
    message = error.what();
  }
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &previous_limit), 0);
  std::signal(SIGXFSZ, previous_handler);

  EXPECT_NE(
      message.find(fmt::format("cannot write '{}': File too large (writing)", target.string())),
      std::string::npos)
      << message;
  EXPECT_EQ(slurp(target), "the old, complete content\n");
  EXPECT_EQ(entries(), std::vector<std::string>{"model.csv"});
}

TEST_F(AtomicFileTest, FilesWrittenTogetherAreAllReplaced) {
  put(dir_ / "model.json", "old model\n");
  const FileContent files[] = {{dir_ / "model.json", "new model\n"},
                               {dir_ / "report.md", "new report\n"}};
  write_files_atomically(files);
  EXPECT_EQ(slurp(dir_ / "model.json"), "new model\n");
  EXPECT_EQ(slurp(dir_ / "report.md"), "new report\n");
  EXPECT_EQ(entries(), (std::vector<std::string>{"model.json", "report.md"}));
}

// The second file cannot be written (its folder is a file): the first, whose content was already
// staged, is left as it was, and no temporary file stays behind.
TEST_F(AtomicFileTest, FilesWrittenTogetherAreAllKeptWhenOneFails) {
  put(dir_ / "model.json", "old model\n");
  put(dir_ / "notes", "a file\n");
  const fs::path report = dir_ / "notes" / "report.md";
  const FileContent files[] = {{dir_ / "model.json", "new model\n"}, {report, "new report\n"}};
  EXPECT_HYST_ERROR(write_files_atomically(files),
                    fmt::format("cannot write '{}': '{}' is not a folder", report.string(),
                                (dir_ / "notes").string()));
  EXPECT_EQ(slurp(dir_ / "model.json"), "old model\n");
  EXPECT_EQ(entries(), (std::vector<std::string>{"model.json", "notes"}));
}

TEST_F(AtomicFileTest, ExistingFolderAsTargetThrowsAndIsKept) {
  const fs::path target = dir_ / "folder";
  fs::create_directory(target);
  EXPECT_HYST_ERROR(write_file_atomically(target, "x"),
                    fmt::format("cannot write '{}': it is a folder, not a file", target.string()));
  EXPECT_TRUE(fs::is_directory(target));
  EXPECT_EQ(entries(), std::vector<std::string>{"folder"});
}

TEST_F(AtomicFileTest, PathWithoutAFileNameThrows) {
  const fs::path target = dir_ / "";
  EXPECT_HYST_ERROR(
      write_file_atomically(target, "x"),
      fmt::format("cannot write '{}': the path does not name a file", target.string()));
  EXPECT_HYST_ERROR(write_file_atomically(dir_ / "..", "x"), "the path does not name a file");
}

TEST_F(AtomicFileTest, ReadFileErrorsNameThePathAndTheReason) {
  const fs::path missing = dir_ / "x.csv";
  EXPECT_HYST_ERROR(read_file(missing),
                    fmt::format("cannot open '{}': No such file or directory", missing.string()));
  EXPECT_HYST_ERROR(read_file(dir_),
                    fmt::format("cannot read '{}': Is a directory", dir_.string()));
}

}  // namespace
}  // namespace hyst::io
