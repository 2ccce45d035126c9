// write_output_file: regular files replaced atomically with their permission
// bits, links followed, devices and FIFOs written in place, read-only files
// refused, write errors reported.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <string>
#include <thread>

#include "common/scratch_files.h"
#include "gab/mesh/file_io.h"

namespace gab {
namespace {

using gab_test::read_file;
using gab_test::scratch_entries;
using gab_test::scratch_path;
using gab_test::write_scratch_file;

mode_t mode_of(const std::string& path) {
  struct stat st;
  return ::lstat(path.c_str(), &st) == 0 ? st.st_mode : 0;
}

TEST(OutputFile, RegularFilesAreReplacedWithTheirPermissionsAndNoLeftovers) {
  const std::string path = write_scratch_file("out.gab", "old");
  ASSERT_EQ(::chmod(path.c_str(), 0640), 0);
  ASSERT_TRUE(write_output_file(path, "new bytes").ok());
  EXPECT_EQ(read_file(path), "new bytes");
  EXPECT_EQ(mode_of(path) & 07777, 0640u);
  const std::string fresh = scratch_path("fresh.gab");
  ASSERT_TRUE(write_output_file(fresh, "x").ok());
  EXPECT_EQ(read_file(fresh), "x");
  EXPECT_TRUE(scratch_entries("out.gab.gab-partial").empty());
  EXPECT_TRUE(scratch_entries("fresh.gab.gab-partial").empty());
}

TEST(OutputFile, SymbolicLinksAreFollowed) {
  const std::string target = write_scratch_file("target.gab", "old");
  const std::string link = scratch_path("link.gab");
  ASSERT_EQ(::symlink("target.gab", link.c_str()), 0);  // relative to the link's folder
  ASSERT_TRUE(write_output_file(link, "through the link").ok());
  EXPECT_TRUE(S_ISLNK(mode_of(link)));
  EXPECT_EQ(read_file(target), "through the link");
  // A dangling link: its target is created.
  const std::string dangling = scratch_path("dangling.gab");
  ASSERT_EQ(::symlink(scratch_path("made.gab").c_str(), dangling.c_str()), 0);
  ASSERT_TRUE(write_output_file(dangling, "made").ok());
  EXPECT_TRUE(S_ISLNK(mode_of(dangling)));
  EXPECT_EQ(read_file(scratch_path("made.gab")), "made");
  // A loop is an error, not a hang.
  const std::string a = scratch_path("loop_a"), b = scratch_path("loop_b");
  ASSERT_EQ(::symlink(b.c_str(), a.c_str()), 0);
  ASSERT_EQ(::symlink(a.c_str(), b.c_str()), 0);
  EXPECT_EQ(write_output_file(a, "x").message(), a + ": cannot write: Too many levels of symbolic links");
}

TEST(OutputFile, ReadOnlyFilesAreRefusedEvenForRoot) {
  const std::string path = write_scratch_file("read_only.gab", "keep me");
  ASSERT_EQ(::chmod(path.c_str(), 0444), 0);
  const Status s = write_output_file(path, "x");
  EXPECT_EQ(s.code(), StatusCode::kIoError);
  // As root the permission bits decide; otherwise the system's EACCES.
  if (::geteuid() == 0) {
    EXPECT_EQ(s.message(), path + ": cannot write: the file is read-only (make it writable or remove it first)");
  } else {
    EXPECT_EQ(s.message(), path + ": cannot write: Permission denied");
  }
  EXPECT_EQ(read_file(path), "keep me");
  const std::string dir = scratch_path("a_dir");
  ASSERT_EQ(::mkdir(dir.c_str(), 0700), 0);
  EXPECT_EQ(write_output_file(dir, "x").message(), dir + ": cannot write: Is a directory");
}

TEST(OutputFile, DevicesAreWrittenInPlaceAndTheirErrorsReported) {
  ASSERT_TRUE(write_output_file("/dev/null", "discarded").ok());
  EXPECT_TRUE(S_ISCHR(mode_of("/dev/null")));
  if (::access("/dev/full", W_OK) != 0) GTEST_SKIP() << "no writable /dev/full here";
  EXPECT_EQ(write_output_file("/dev/full", "x").message(), "/dev/full: cannot write: No space left on device");
  EXPECT_TRUE(S_ISCHR(mode_of("/dev/full")));
}

TEST(OutputFile, AFifoIsWrittenInPlace) {
  const std::string fifo = scratch_path("pipe");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string got;
  std::thread reader([&] { got = read_file(fifo); });
  const Status s = write_output_file(fifo, "through the pipe");
  if (!s.ok()) {
    // Release the reader, still waiting for a writer to open the FIFO.
    const int fd = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK);
    if (fd >= 0) ::close(fd);
  }
  reader.join();
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(got, "through the pipe");
  EXPECT_TRUE(S_ISFIFO(mode_of(fifo)));
}

TEST(OutputFile, ADescriptorPathIsWrittenInPlace) {
  // /dev/fd/N of a pipe: no rename could reach it.
  int ends[2];
  ASSERT_EQ(::pipe(ends), 0);
  const Status s = write_output_file("/dev/fd/" + std::to_string(ends[1]), "to the descriptor");
  ::close(ends[1]);
  ASSERT_TRUE(s.ok()) << s.message();
  char buf[64];
  const ssize_t got = ::read(ends[0], buf, sizeof(buf));
  ::close(ends[0]);
  EXPECT_EQ(std::string(buf, got > 0 ? static_cast<size_t>(got) : 0), "to the descriptor");
}

}  // namespace
}  // namespace gab
