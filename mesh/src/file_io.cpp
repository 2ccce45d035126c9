// POSIX file access. The atomic write relies on rename(2) replacing the
// target in one step within a file system, so a reader sees the old file or
// the new one, never a partial write; what rename would destroy (a device, a
// FIFO, a link) is written in place or followed instead.
#include "gab/mesh/file_io.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>

namespace gab {

namespace {

Status io_error(const std::string& path, const char* what, int err) {
  return Status::Error(StatusCode::kIoError, path + ": " + what + ": " + std::strerror(err));
}

}  // namespace

Status read_file(const std::string& path, std::string* bytes) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return io_error(path, "cannot open", errno);
  struct stat st;
  if (::fstat(fd, &st) != 0) {
    const int err = errno;
    ::close(fd);
    return io_error(path, "cannot open", err);
  }
  if (S_ISDIR(st.st_mode)) {
    ::close(fd);
    return io_error(path, "cannot open", EISDIR);
  }
  std::string data;
  // The size is a hint only (pipes and /proc files report 0): read to EOF.
  if (S_ISREG(st.st_mode) && st.st_size > 0) data.reserve(static_cast<size_t>(st.st_size));
  char buf[1 << 16];
  for (;;) {
    const ssize_t got = ::read(fd, buf, sizeof(buf));
    if (got == 0) break;
    if (got < 0) {
      if (errno == EINTR) continue;
      const int err = errno;
      ::close(fd);
      return io_error(path, "read error", err);
    }
    data.append(buf, static_cast<size_t>(got));
  }
  ::close(fd);
  *bytes = std::move(data);
  return Status::Ok();
}

namespace {

// The temporary files of the writes in progress, for remove_partial_outputs
// (a signal handler): fixed slots of lock-free atomics and plain bytes, no
// allocation. A slot: 0 free, 1 being filled, 2 holding a path.
constexpr int kPartialSlots = 16;
constexpr size_t kPartialPathBytes = 4096;
struct PartialSlot {
  std::atomic<int> state{0};
  char path[kPartialPathBytes];
};
PartialSlot partial_slots[kPartialSlots];
static_assert(std::atomic<int>::is_always_lock_free, "a signal handler reads the slots");

// Registers `path` (returns its slot, or -1 when none is free or the path
// too long: that write is still correct, only not cleaned up on a signal).
int register_partial(const std::string& path) {
  if (path.size() >= kPartialPathBytes) return -1;
  for (int i = 0; i < kPartialSlots; ++i) {
    int expected = 0;
    if (partial_slots[i].state.compare_exchange_strong(expected, 1)) {
      std::memcpy(partial_slots[i].path, path.c_str(), path.size() + 1);
      partial_slots[i].state.store(2, std::memory_order_release);
      return i;
    }
  }
  return -1;
}

void unregister_partial(int slot) {
  if (slot >= 0) partial_slots[slot].state.store(0, std::memory_order_release);
}

// Writes all of `bytes` to `fd`; 0 or the errno of the failure.
int write_all(int fd, std::string_view bytes) {
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t put = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (put < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    done += static_cast<size_t>(put);
  }
  return 0;
}

// A device, FIFO or descriptor: written where it is.
Status write_in_place(const std::string& path, std::string_view bytes) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) return io_error(path, "cannot write", errno);
  int err = write_all(fd, bytes);
  if (::close(fd) != 0 && err == 0) err = errno;
  return err == 0 ? Status::Ok() : io_error(path, "cannot write", err);
}

// A temporary file beside `target`, renamed over it; `mode` its permission
// bits and flushed to disk first when `keep_mode` (a file replaced; else
// 0666 less the umask, a new file). Errors name `path`.
Status replace_atomically(const std::string& path, const std::string& target, std::string_view bytes,
                          mode_t mode, bool keep_mode) {
  static std::atomic<unsigned> counter{0};
  std::string temp;
  int fd = -1;
  for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
    temp = target + ".gab-partial-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
    fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0 && errno != EEXIST) return io_error(path, "cannot write", errno);
  }
  if (fd < 0) return io_error(path, "cannot write", EEXIST);
  const int slot = register_partial(temp);
  int err = write_all(fd, bytes);
  if (err == 0 && keep_mode && ::fchmod(fd, mode) != 0) err = errno;
  if (err == 0 && keep_mode && ::fsync(fd) != 0) err = errno;  // a file replaced: durable first
  if (::close(fd) != 0 && err == 0) err = errno;
  if (err == 0 && ::rename(temp.c_str(), target.c_str()) != 0) err = errno;
  if (err != 0) ::unlink(temp.c_str());
  unregister_partial(slot);
  return err == 0 ? Status::Ok() : io_error(path, "cannot write", err);
}

// /dev/stdout, /dev/fd/N and the like name a descriptor, which may be a
// pipe: written in place whatever it is.
bool names_descriptor(const std::string& path) {
  return path == "/dev/stdout" || path == "/dev/stderr" || path.rfind("/dev/fd/", 0) == 0 ||
         path.rfind("/proc/self/fd/", 0) == 0;
}

// Where the chain of symbolic links starting at `path` ends (`path` itself
// when it is no link); kIoError past 40 links (ELOOP).
Status link_target(const std::string& path, std::string* target) {
  std::string at = path;
  for (int depth = 0; depth < 40; ++depth) {
    struct stat st;
    if (::lstat(at.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) {
      *target = at;
      return Status::Ok();
    }
    std::string link(static_cast<size_t>(st.st_size > 0 ? st.st_size : 4096) + 1, '\0');
    const ssize_t got = ::readlink(at.c_str(), &link[0], link.size());
    if (got < 0) return io_error(path, "cannot write", errno);
    link.resize(static_cast<size_t>(got));
    const size_t slash = at.find_last_of('/');
    at = link[0] == '/' || slash == std::string::npos ? link : at.substr(0, slash + 1) + link;
  }
  return io_error(path, "cannot write", ELOOP);
}

}  // namespace

Status write_output_file(const std::string& path, std::string_view bytes) {
  if (names_descriptor(path)) return write_in_place(path, bytes);
  std::string target;
  GAB_RETURN_IF_ERROR(link_target(path, &target));
  struct stat st;
  if (::stat(target.c_str(), &st) != 0) {
    if (errno != ENOENT) return io_error(path, "cannot write", errno);
    return replace_atomically(path, target, bytes, 0, false);
  }
  if (S_ISDIR(st.st_mode)) return io_error(path, "cannot write", EISDIR);
  if (!S_ISREG(st.st_mode)) return write_in_place(target, bytes);
  if (::access(target.c_str(), W_OK) != 0) return io_error(path, "cannot write", errno);
  if ((st.st_mode & (S_IWUSR | S_IWGRP | S_IWOTH)) == 0) {
    return Status::Error(StatusCode::kIoError,
                         path + ": cannot write: the file is read-only (make it writable or remove it first)");
  }
  return replace_atomically(path, target, bytes, st.st_mode & 07777, true);
}

Status check_output_file(const std::string& path, const std::vector<std::string>& inputs) {
  if (names_descriptor(path)) return Status::Ok();
  std::string target;
  GAB_RETURN_IF_ERROR(link_target(path, &target));
  struct stat st;
  if (::stat(target.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) return io_error(path, "cannot write", EISDIR);
    for (const std::string& input : inputs) {
      struct stat in;
      if (::stat(input.c_str(), &in) == 0 && in.st_dev == st.st_dev && in.st_ino == st.st_ino) {
        return Status::Error(StatusCode::kInvalidArgument,
                             "the output " + path + " is the input " + input + ": writing it would replace the input");
      }
    }
    return Status::Ok();
  }
  if (errno != ENOENT) return io_error(path, "cannot write", errno);
  const size_t slash = target.find_last_of('/');
  const std::string folder = slash == std::string::npos ? "." : slash == 0 ? "/" : target.substr(0, slash);
  struct stat fs;
  if (::stat(folder.c_str(), &fs) != 0 || !S_ISDIR(fs.st_mode)) {
    return Status::Error(StatusCode::kIoError, path + ": cannot write: the folder " + folder + " does not exist");
  }
  return Status::Ok();
}

void remove_partial_outputs() noexcept {
  for (PartialSlot& slot : partial_slots) {
    if (slot.state.load(std::memory_order_acquire) == 2) ::unlink(slot.path);
  }
}

}  // namespace gab
