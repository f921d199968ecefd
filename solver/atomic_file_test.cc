#include "solver/atomic_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "scene/input_error.h"

namespace ivv {
namespace {

namespace fs = std::filesystem;

// A fresh directory per test under the system's temporary directory.
class AtomicFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("ivv_atomic_" + std::to_string(getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  static std::string slurp(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  }
  static void write(const fs::path& p, const std::string& text, const std::string& field = "--out",
                    Stdout dash = Stdout::refused) {
    write_file_atomically(
        p, [&](std::ostream& os) { os << text; }, field, dash);
  }
  // The InputError's field, or "" when no InputError was thrown.
  static std::string rejected_field(const fs::path& p, const std::string& field = "--out") {
    try {
      write(p, "x", field);
    } catch (const InputError& e) {
      return e.field();
    }
    return "";
  }
  fs::path dir_;
};

TEST_F(AtomicFile, NewPathIsWritten) {
  write(dir_ / "a.csv", "hello");
  EXPECT_EQ(slurp(dir_ / "a.csv"), "hello");
}

// A symlink given as --out or --trajectory used to be replaced by a regular file, its target
// left stale.
TEST_F(AtomicFile, SymlinkIsFollowedAndKept) {
  write(dir_ / "target.csv", "old");
  fs::create_symlink("target.csv", dir_ / "link.csv");
  write(dir_ / "link.csv", "new");
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir_ / "link.csv")));
  EXPECT_EQ(slurp(dir_ / "target.csv"), "new");
}

TEST_F(AtomicFile, ChainOfSymlinksAndDanglingLinkReachTheFinalTarget) {
  fs::create_directories(dir_ / "sub");
  fs::create_symlink(dir_ / "sub" / "final.csv", dir_ / "l2");  // dangling, absolute
  fs::create_symlink("l2", dir_ / "l1");
  write(dir_ / "l1", "content");
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir_ / "l1")));
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir_ / "l2")));
  EXPECT_EQ(slurp(dir_ / "sub" / "final.csv"), "content");
}

TEST_F(AtomicFile, SymlinkCycleIsRejected) {
  fs::create_symlink("b", dir_ / "a");
  fs::create_symlink("a", dir_ / "b");
  EXPECT_EQ(rejected_field(dir_ / "a"), "--out");
}

TEST_F(AtomicFile, ExistingFileKeepsItsPermissions) {
  write(dir_ / "p.csv", "old");
  fs::permissions(dir_ / "p.csv", fs::perms::owner_read | fs::perms::owner_write);
  write(dir_ / "p.csv", "new");
  EXPECT_EQ(fs::status(dir_ / "p.csv").permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write);
}

// A device node (/dev/stdout, /dev/full) was replaced by a regular file (as root, a system file).
TEST_F(AtomicFile, DeviceIsRejectedAndLeftAlone) {
  EXPECT_EQ(rejected_field("/dev/null", "--trajectory"), "--trajectory");
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
  // a link to a device is judged by its target
  fs::create_symlink("/dev/null", dir_ / "null_link");
  EXPECT_EQ(rejected_field(dir_ / "null_link"), "--out");
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

TEST_F(AtomicFile, FifoIsRejected) {
  ASSERT_EQ(mkfifo((dir_ / "fifo").c_str(), 0600), 0);
  EXPECT_EQ(rejected_field(dir_ / "fifo"), "--out");
}

// `sweep --out /dev/stdout | cat` ran the whole sweep, then failed: the
// magic link /proc/self/fd/N reads as "pipe:[...]", which looked like a new file in /proc.
TEST_F(AtomicFile, PipeBehindAMagicLinkIsRejectedBeforeAnyWork) {
  int fds[2];
  ASSERT_EQ(pipe(fds), 0);
  const fs::path magic = "/proc/self/fd/" + std::to_string(fds[1]);
  EXPECT_EQ(rejected_field(magic), "--out");
  close(fds[0]);
  close(fds[1]);
}

// A run killed while writing left ".NAME.tmpPID-N" for ever (tens of MB for a large sweep).
TEST_F(AtomicFile, TemporariesOfDeadProcessesAreRemovedOthersKept) {
  const pid_t child = fork();
  if (child == 0) _exit(0);
  ASSERT_GT(child, 0);
  waitpid(child, nullptr, 0);  // reaped: no process has this PID now
  const fs::path dead = dir_ / (".g.csv.tmp" + std::to_string(child) + "-12");
  const fs::path mine = dir_ / (".g.csv.tmp" + std::to_string(getpid()) + "-3");
  const fs::path other_file = dir_ / (".h.csv.tmp" + std::to_string(child) + "-12");
  for (const fs::path& p : {dead, mine, other_file}) std::ofstream(p) << "x";
  EXPECT_EQ(remove_stale_temporaries(dir_ / "g.csv"), 1u);
  EXPECT_FALSE(fs::exists(dead));
  EXPECT_TRUE(fs::exists(mine));        // this process may still be writing it
  EXPECT_TRUE(fs::exists(other_file));  // another destination's
}

// A staged file is in place only once committed; dropped uncommitted, it leaves nothing.
TEST_F(AtomicFile, StagedFileAppearsOnlyOnCommit) {
  {
    StagedFile staged(dir_ / "a.json", [](std::ostream& out) { out << "{}"; });
    EXPECT_FALSE(fs::exists(dir_ / "a.json"));
  }
  EXPECT_TRUE(fs::is_empty(dir_));
  StagedFile staged(dir_ / "a.json", [](std::ostream& out) { out << "{}"; });
  staged.commit();
  EXPECT_EQ(slurp(dir_ / "a.json"), "{}");
}

// A file written already (a sweep's partial CSV) is staged by a rename: the source is gone at
// once, the destination appears only on commit, and an uncommitted stage leaves nothing.
TEST_F(AtomicFile, StagedFromAFileTakesTheFileAndAppearsOnlyOnCommit) {
  std::ofstream(dir_ / "a.csv.partial") << "v0,e\n1,0.5\n";
  {
    StagedFile staged(dir_ / "a.csv", StagedFile::FromFile{dir_ / "a.csv.partial"});
    EXPECT_FALSE(fs::exists(dir_ / "a.csv.partial"));
    EXPECT_FALSE(fs::exists(dir_ / "a.csv"));
  }
  EXPECT_TRUE(fs::is_empty(dir_));
  std::ofstream(dir_ / "a.csv.partial") << "v0,e\n1,0.5\n";
  StagedFile staged(dir_ / "a.csv", StagedFile::FromFile{dir_ / "a.csv.partial"});
  staged.commit();
  EXPECT_EQ(slurp(dir_ / "a.csv"), "v0,e\n1,0.5\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1);
}

// Either way of replacing leaves the new content with the old file's permissions, and nothing
// else in the directory; after_removing also commits where no file was before.
TEST_F(AtomicFile, CommitAfterRemovingReplacesAndKeepsPermissionsAsARenameDoes) {
  for (const StagedFile::Replace how :
       {StagedFile::Replace::atomically, StagedFile::Replace::after_removing}) {
    std::ofstream(dir_ / "a.csv") << "old\n";
    fs::permissions(dir_ / "a.csv", fs::perms::owner_read | fs::perms::owner_write);
    StagedFile staged(dir_ / "a.csv", [](std::ostream& out) { out << "new\n"; });
    EXPECT_EQ(slurp(dir_ / "a.csv"), "old\n");
    staged.commit(how);
    EXPECT_EQ(slurp(dir_ / "a.csv"), "new\n");
    EXPECT_EQ(fs::status(dir_ / "a.csv").permissions(),
              fs::perms::owner_read | fs::perms::owner_write);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1);
    fs::remove(dir_ / "a.csv");
  }
  StagedFile fresh(dir_ / "b.csv", [](std::ostream& out) { out << "b\n"; });
  fresh.commit(StagedFile::Replace::after_removing);
  EXPECT_EQ(slurp(dir_ / "b.csv"), "b\n");
}

TEST_F(AtomicFile, DirectoryAndEmptyPathAreRejectedNamingTheFlag) {
  EXPECT_EQ(rejected_field(dir_), "--out");
  EXPECT_EQ(rejected_field(dir_ / "."), "--out");
  EXPECT_EQ(rejected_field(""), "--out");
  EXPECT_EQ(rejected_field(dir_ / "missing" / "x.csv"), "--out");
  EXPECT_TRUE(fs::is_empty(dir_));
}

TEST_F(AtomicFile, DashIsStandardOutputOnlyWhereAllowed) {
  EXPECT_EQ(rejected_field("-"), "--out");
  ::testing::internal::CaptureStdout();
  write("-", "to stdout", "--out", Stdout::allowed);
  EXPECT_EQ(::testing::internal::GetCapturedStdout(), "to stdout");
  EXPECT_FALSE(fs::exists("-"));
}

TEST_F(AtomicFile, FailedWriteLeavesNoFile) {
  EXPECT_THROW(write_file_atomically(dir_ / "f.csv",
                                     [](std::ostream&) { throw std::runtime_error("boom"); }),
               std::runtime_error);
  EXPECT_TRUE(fs::is_empty(dir_));
}

}  // namespace
}  // namespace ivv
