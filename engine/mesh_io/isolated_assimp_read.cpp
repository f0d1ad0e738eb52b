#include "mesh_io/isolated_assimp_read.h"

#include "mesh_io/available_memory.h"
#include "mesh_io/byte_count_text.h"
#include "mesh_io/read_memory_limit.h"
#include "mesh_io/regular_file_io_system.h"
#include "mesh_io/texture_references.h"
#include "mesh_io/whole_fd_io.h"

#include <assimp/Importer.hpp>
#include <assimp/ProgressHandler.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <fmt/format.h>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <new>
#include <string>
#include <utility>
#include <vector>

namespace mhd {
namespace {

// The child's answer is a run of records: a kind byte, the payload's length (8 bytes),
// the payload. Vertices and triangles come in pieces of at most kPieceBytes.
enum class Record : char {
  Progress = 'p',   // a double, the fraction done
  Error = 'e',      // the reason, as text
  Counts = 'c',     // vertices and faces in all, for the parent's reserve
  Vertices = 'v',   // floats, x y z per vertex
  Triangles = 't',  // uint32 corners, three per triangle, numbered across meshes
  Done = 'd',       // faces dropped, then 1 if the corners are unshared
  Allowance = 'm',  // a uint64, the memory the reader may now take (ReadMemoryLimit)
};
constexpr std::size_t kPieceBytes = std::size_t{4} << 20;
constexpr std::uint64_t kMaxTextBytes = 1 << 16;
// The child's exit status when an allocation went past its memory limit.
constexpr int kOutOfMemoryStatus = 4;

// ---- the reader, in the child (or here, where no child can start) ----

// Where the reader's records go: the pipe to the parent, or this process's read. False
// when they are no longer wanted (the parent stopped listening, the read is over).
using RecordSink = std::function<bool(Record kind, const void* payload, std::uint64_t bytes)>;

bool send_text(const RecordSink& sink, Record kind, const std::string& text) {
  return sink(kind, text.data(), std::min<std::uint64_t>(text.size(), kMaxTextBytes));
}

/// Forwards assimp's progress to the parent (owned and deleted by the Importer).
class SendProgress final : public Assimp::ProgressHandler {
 public:
  explicit SendProgress(const RecordSink& sink) : sink_(sink) {}
  bool Update(float percentage) override {
    const double fraction = std::clamp(static_cast<double>(percentage), 0.0, 1.0);
    if (percentage >= 0.0f) (void)sink_(Record::Progress, &fraction, sizeof(fraction));
    return true;  // never abort
  }

 private:
  const RecordSink& sink_;
};

/// "" when every face of every mesh has a corner, else which face has none.
std::string face_without_corners(const aiScene& scene) {
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    const aiMesh* am = scene.mMeshes[m];
    if (am == nullptr) continue;
    for (unsigned f = 0; f < am->mNumFaces; ++f) {
      if (am->mFaces[f].mNumIndices != 0) continue;
      if (scene.mNumMeshes == 1) return fmt::format("face {} has no vertex indices", f);
      return fmt::format("face {} of mesh {} has no vertex indices", f, m);
    }
  }
  return {};
}

bool is_triangle_mesh(const aiMesh* am) {
  return am != nullptr && (am->mPrimitiveTypes & aiPrimitiveType_TRIANGLE) != 0;
}

// Reads the file and sends the answer; false if the sink stopped taking it. `on_open`,
// if set, sees each file assimp opens.
bool read_and_send(const std::filesystem::path& file, bool report_progress, const RecordSink& sink,
                   const RegularFileIoSystem::OpenSeen& on_open) {
  Assimp::Importer importer;
  auto* io = new RegularFileIoSystem();  // owned by the importer
  if (on_open) io->set_on_open(on_open);
  importer.SetIOHandler(io);
  // Keep positions only, so vertices that differ only in normals, UVs or colours
  // (flat-shaded or STL files) join into one. SortByPType splits point and line
  // primitives into meshes of their own, which are skipped below (not removed by
  // assimp, which would fail a file without triangles with a less helpful message).
  importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS,
                              aiComponent_NORMALS | aiComponent_TANGENTS_AND_BITANGENTS | aiComponent_COLORS |
                                  aiComponent_TEXCOORDS | aiComponent_BONEWEIGHTS | aiComponent_ANIMATIONS |
                                  aiComponent_TEXTURES | aiComponent_LIGHTS | aiComponent_CAMERAS);
  if (report_progress) importer.SetProgressHandler(new SendProgress(sink));
  // No aiProcess_JoinIdenticalVertices: on an already indexed 1M-triangle PLY it costs
  // 0.65 s to find nothing to join. Files that arrive unshared are welded by the loader.
  // ValidateDataStructure runs first: without it a face index past the vertices (a
  // hostile PLY, found by mhd-fuzz-mesh-header) crashes assimp's later steps.
  // The steps after the read run apart from it, once the faces are known to be sound:
  // a face with no corners is typed a polygon by assimp 5.2.5, whose triangulation then
  // aborts (and ValidateDataStructure runs before the faces are typed).
  const aiScene* scene = importer.ReadFile(file.string(), aiProcess_ValidateDataStructure);
  if (!io->refusals().empty()) return send_text(sink, Record::Error, fmt::format("side file {}", io->refusals().front()));
  if (const std::string texture = texture_problem(scene, file); !texture.empty()) {
    return send_text(sink, Record::Error, texture);
  }
  if (scene != nullptr) {
    if (const std::string empty = face_without_corners(*scene); !empty.empty()) {
      return send_text(sink, Record::Error, empty);
    }
    scene = importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_PreTransformVertices |
                                         aiProcess_SortByPType | aiProcess_RemoveComponent);
  }
  if (scene == nullptr) {
    std::string why = importer.GetErrorString();
    if (why.empty()) why = "unknown error";
    return send_text(sink, Record::Error, fmt::format("assimp could not read it: {}", why));
  }

  std::array<std::uint64_t, 2> counts{};  // vertices, faces
  std::uint64_t triangle_meshes = 0;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    if (!is_triangle_mesh(scene->mMeshes[m])) continue;
    counts[0] += scene->mMeshes[m]->mNumVertices;
    counts[1] += scene->mMeshes[m]->mNumFaces;
    ++triangle_meshes;
  }
  if (counts[0] >= std::numeric_limits<std::uint32_t>::max()) {
    return send_text(sink, Record::Error, fmt::format("too many vertices ({})", counts[0]));
  }
  if (!sink(Record::Counts, counts.data(), sizeof(counts))) return false;
  std::uint64_t dropped = 0;
  std::uint32_t base = 0;
  std::vector<std::uint32_t> corners;
  corners.reserve(kPieceBytes / sizeof(std::uint32_t));
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* am = scene->mMeshes[m];
    if (!is_triangle_mesh(am)) continue;
    static_assert(sizeof(aiVector3D) == 3 * sizeof(float));
    const std::size_t per_piece = kPieceBytes / sizeof(aiVector3D);
    for (std::size_t i = 0; i < am->mNumVertices; i += per_piece) {
      const std::size_t n = std::min<std::size_t>(per_piece, am->mNumVertices - i);
      if (!sink(Record::Vertices, am->mVertices + i, n * sizeof(aiVector3D))) return false;
    }
    for (unsigned f = 0; f < am->mNumFaces; ++f) {
      const aiFace& face = am->mFaces[f];
      if (face.mNumIndices != 3) {
        ++dropped;
        continue;
      }
      // An index past this mesh's vertices is made invalid so the clean-up drops it.
      for (unsigned k = 0; k < 3; ++k) {
        const unsigned i = face.mIndices[k];
        corners.push_back(i < am->mNumVertices ? base + i : std::numeric_limits<std::uint32_t>::max());
      }
      if (corners.size() + 3 > corners.capacity()) {
        if (!sink(Record::Triangles, corners.data(), corners.size() * sizeof(std::uint32_t))) return false;
        corners.clear();
      }
    }
    base += am->mNumVertices;
  }
  if (!corners.empty() && !sink(Record::Triangles, corners.data(), corners.size() * sizeof(std::uint32_t))) {
    return false;
  }
  const std::array<std::uint64_t, 2> done{dropped, triangle_meshes > 1 || counts[0] > counts[1] ? 1U : 0U};
  return sink(Record::Done, done.data(), sizeof(done));
}

[[noreturn]] void run_child(const std::filesystem::path& file, bool report_progress, int fd,
                            const MeshReadLimits& limits, std::uint64_t available_bytes) {
  // A crash must end the child by its signal for the parent to name it, not in a
  // handler the parent installed (a sanitizer's, a fuzzer's).
  for (const int s : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) ::signal(s, SIG_DFL);
  const RecordSink to_parent = [fd](Record kind, const void* payload, std::uint64_t bytes) {
    std::array<char, 9> head{};
    head[0] = static_cast<char>(kind);
    std::memcpy(head.data() + 1, &bytes, sizeof(bytes));
    return write_all(fd, head.data(), head.size()) && write_all(fd, payload, bytes);
  };
  // Bounded memory: an allocation past the limit ends the child at once, with a status the
  // parent names (assimp would catch the bad_alloc, or meet it where it cannot).
  ReadMemoryLimit memory(limits.memory_base_bytes, limits.memory_per_file_byte, available_bytes);
  const auto tell_allowance = [&] {
    const std::uint64_t allowance = memory.allowance_bytes();
    return to_parent(Record::Allowance, &allowance, sizeof(allowance));
  };
  RegularFileIoSystem::OpenSeen on_open;
  if (memory.start()) {
    std::set_new_handler([] { ::_exit(kOutOfMemoryStatus); });
    if (!tell_allowance()) ::_exit(3);
    on_open = [&](const std::string& path, std::uint64_t bytes) {
      if (memory.add_file(path, bytes)) (void)tell_allowance();
    };
  }
  const bool sent = read_and_send(file, report_progress, to_parent, on_open);
  // _exit: nothing of the parent's (stdio buffers, atexit handlers) runs twice.
  ::_exit(sent ? 0 : 3);
}

// ---- the records, taken into the read ----

// What one record did to the read.
struct Taken {
  enum class Kind { More, Done, Failed };
  Kind kind = Kind::More;
  std::string error;  // when Failed
};

Taken failed(std::string error) { return {Taken::Kind::Failed, std::move(error)}; }

Taken take(Record kind, const char* payload, std::uint64_t bytes, AssimpRead& read, std::uint64_t& allowance_bytes,
           const std::function<void(double)>& progress) {
  switch (kind) {
    case Record::Allowance:
      if (bytes != sizeof(allowance_bytes)) return failed("assimp's reader sent a malformed memory limit");
      std::memcpy(&allowance_bytes, payload, sizeof(allowance_bytes));
      return {};
    case Record::Progress: {
      double fraction = 0.0;
      if (bytes == sizeof(fraction)) std::memcpy(&fraction, payload, sizeof(fraction));
      if (progress && std::isfinite(fraction)) progress(std::clamp(fraction, 0.0, 1.0));
      return {};
    }
    case Record::Error:
      return failed(std::string(payload, bytes));
    case Record::Counts: {
      std::array<std::uint64_t, 2> counts{};
      if (bytes != sizeof(counts)) return failed("assimp's reader sent malformed counts");
      std::memcpy(counts.data(), payload, sizeof(counts));
      read.mesh.vertices_m.reserve(counts[0]);
      read.mesh.triangles.reserve(counts[1]);
      return {};
    }
    case Record::Vertices: {
      const std::size_t n = bytes / (3 * sizeof(float));
      for (std::size_t i = 0; i < n; ++i) {
        std::array<float, 3> xyz{};
        std::memcpy(xyz.data(), payload + i * sizeof(xyz), sizeof(xyz));
        read.mesh.vertices_m.emplace_back(static_cast<double>(xyz[0]), static_cast<double>(xyz[1]),
                                          static_cast<double>(xyz[2]));
      }
      return {};
    }
    case Record::Triangles: {
      const std::size_t n = bytes / sizeof(TriangleIndices);
      const std::size_t at = read.mesh.triangles.size();
      read.mesh.triangles.resize(at + n);
      std::memcpy(read.mesh.triangles.data() + at, payload, n * sizeof(TriangleIndices));
      return {};
    }
    case Record::Done: {
      std::array<std::uint64_t, 2> done{};
      if (bytes != sizeof(done)) return failed("assimp's reader sent a malformed end");
      std::memcpy(done.data(), payload, sizeof(done));
      read.dropped = done[0];
      read.unshared = done[1] != 0;
      return {Taken::Kind::Done, {}};
    }
  }
  return failed(fmt::format("assimp's reader sent a record of unknown kind {}", static_cast<int>(kind)));
}

// The read in this process, where no child could start (`why`): the same records, taken
// as they are made. Nothing bounds its time, and a crash of the reader is this process's.
Result<AssimpRead, std::string> read_here(const std::filesystem::path& file,
                                          const std::function<void(double)>& progress, std::string why) {
  AssimpRead read;
  Taken last;
  std::uint64_t unlimited = 0;  // no memory limit here: no Allowance record comes
  const RecordSink to_read = [&](Record kind, const void* payload, std::uint64_t bytes) {
    last = take(kind, static_cast<const char*>(payload), bytes, read, unlimited, progress);
    return last.kind == Taken::Kind::More;
  };
  (void)read_and_send(file, static_cast<bool>(progress), to_read, {});
  if (last.kind == Taken::Kind::Failed) return std::move(last.error);
  if (last.kind != Taken::Kind::Done) return std::string("assimp's reader ended without an answer");
  read.unisolated_read = std::move(why);
  return read;
}

// ---- the parent ----

using Clock = std::chrono::steady_clock;

enum class Got { Bytes, End, Late };

// Reads exactly `bytes` into `out` before `deadline`: End if the child closed the pipe
// first, Late if the deadline passed.
Got read_exactly(int fd, void* out, std::size_t bytes, Clock::time_point deadline) {
  char* p = static_cast<char*>(out);
  while (bytes > 0) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) return Got::Late;
    pollfd pfd{fd, POLLIN, 0};
    const int ready = ::poll(&pfd, 1, static_cast<int>(std::min<long long>(left, 1000)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;
    const ssize_t n = ::read(fd, p, bytes);
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (n <= 0) return Got::End;
    p += n;
    bytes -= static_cast<std::size_t>(n);
  }
  return Got::Bytes;
}

// `allowance_bytes`: the child's memory limit when it ended (kOutOfMemoryStatus).
std::string how_it_ended(int status, std::uint64_t allowance_bytes, const MeshReadLimits& limits,
                         std::uint64_t available_bytes) {
  if (WIFEXITED(status) && WEXITSTATUS(status) == kOutOfMemoryStatus) {
    const std::string at_most =
        available_bytes > 0 ? fmt::format(", at most the {} available", byte_count_text(available_bytes)) : "";
    return fmt::format("assimp needed more than {} of memory to read it (the limit: {} and {:g} bytes for each byte "
                       "of the files it opened{}); the file may be corrupt",
                       byte_count_text(allowance_bytes), byte_count_text(limits.memory_base_bytes),
                       limits.memory_per_file_byte, at_most);
  }
  if (WIFSIGNALED(status)) {
    const int s = WTERMSIG(status);
    const char* name = ::strsignal(s);
    return fmt::format("assimp crashed reading it (signal {}, {})", s, name != nullptr ? name : "unknown");
  }
  if (WIFEXITED(status)) return fmt::format("assimp crashed reading it (exit status {})", WEXITSTATUS(status));
  return "assimp crashed reading it";
}

/// The child's pipe and process: closed, killed if still running, and reaped on every way out.
class Child {
 public:
  Child(pid_t pid, int fd) : pid_(pid), fd_(fd) {}
  Child(const Child&) = delete;
  Child& operator=(const Child&) = delete;
  ~Child() {
    ::close(fd_);
    if (pid_ > 0) {
      ::kill(pid_, SIGKILL);
      (void)wait();
    }
  }
  [[nodiscard]] int fd() const { return fd_; }
  /// Waits for the child to end; its status.
  int wait() {
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    pid_ = -1;
    return status;
  }

 private:
  pid_t pid_;
  int fd_;
};

}  // namespace

Result<AssimpRead, std::string> read_with_assimp(const std::filesystem::path& file,
                                                 const std::function<void(double)>& progress,
                                                 const MeshReadLimits& limits) {
  std::error_code ec;
  const auto file_bytes = std::filesystem::file_size(file, ec);
  const double limit_s =
      limits.base_s + limits.seconds_per_mib * (ec ? 0.0 : static_cast<double>(file_bytes) / (1024.0 * 1024.0));
  const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                           std::chrono::duration<double>(std::clamp(limit_s, 0.0, 1e7)));
  const std::uint64_t available_bytes = available_memory_bytes();
  std::array<int, 2> ends{};
  if (::pipe2(ends.data(), O_CLOEXEC) != 0) {
    return read_here(file, progress, fmt::format("cannot make a pipe for the reader: {}", std::strerror(errno)));
  }
  // Fewer wake-ups for the pieces (the system's limit applies; the default is kept if refused).
  (void)::fcntl(ends[1], F_SETPIPE_SZ, 1 << 20);
  const pid_t pid = ::fork();
  if (pid < 0) {
    const int err = errno;
    ::close(ends[0]);
    ::close(ends[1]);
    return read_here(file, progress, fmt::format("cannot start a process for the reader: {}", std::strerror(err)));
  }
  if (pid == 0) {
    ::close(ends[0]);
    run_child(file, static_cast<bool>(progress), ends[1], limits, available_bytes);
  }
  ::close(ends[1]);
  Child child(pid, ends[0]);

  AssimpRead read;
  std::uint64_t allowance_bytes = 0;
  const auto ended = [&](int status) { return how_it_ended(status, allowance_bytes, limits, available_bytes); };
  std::vector<char> payload;
  for (;;) {
    std::array<char, 9> head{};
    Got got = read_exactly(child.fd(), head.data(), head.size(), deadline);
    std::uint64_t bytes = 0;
    std::memcpy(&bytes, head.data() + 1, sizeof(bytes));
    const auto kind = static_cast<Record>(head[0]);
    const bool bulk = kind == Record::Vertices || kind == Record::Triangles;
    if (got == Got::Bytes && bytes > (bulk ? kPieceBytes : kMaxTextBytes)) {
      return fmt::format("assimp's reader sent a record of {} bytes", bytes);
    }
    if (got == Got::Bytes) {
      payload.resize(bytes);
      got = read_exactly(child.fd(), payload.data(), payload.size(), deadline);
    }
    if (got == Got::Late) {
      return fmt::format("assimp did not finish reading it within {:.0f} s (the limit for a file of {} bytes); "
                         "its reader may be stuck in a loop",
                         limit_s, ec ? 0 : file_bytes);
    }
    if (got == Got::End) return ended(child.wait());
    Taken taken = take(kind, payload.data(), bytes, read, allowance_bytes, progress);
    if (taken.kind == Taken::Kind::More) continue;
    if (taken.kind == Taken::Kind::Failed) {
      if (kind == Record::Error) (void)child.wait();  // it said why and ends; others are killed
      return std::move(taken.error);
    }
    const int status = child.wait();
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return ended(status);
    return read;
  }
}

}  // namespace mhd
