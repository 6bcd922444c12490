#include "simhuman/dist/mpi_communicator.h"

#include <chrono>
#include <cstdlib>
#include <list>
#include <thread>

#ifdef SIMHUMAN_HAVE_MPI
#include <mpi.h>
#endif

namespace simhuman::dist {
namespace {

// the launcher's rank count from its environment (0 when absent)
[[maybe_unused]] int LauncherSize() {
  for (const char* var : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE", "SLURM_NTASKS"}) {
    const char* v = std::getenv(var);
    if (v && *v) return std::atoi(v);
  }
  return 0;
}

#ifdef SIMHUMAN_HAVE_MPI

constexpr int kPostTag = 7;

absl::Status MpiError(int code, const char* call) {
  char text[MPI_MAX_ERROR_STRING];
  int len = 0;
  MPI_Error_string(code, text, &len);
  return absl::InternalError(std::string("MPI ") + call + " failed: " + std::string(text, len));
}

#define SH_MPI(call)                                                   \
  do {                                                                 \
    int sh_mpi_rc_ = (call);                                           \
    if (sh_mpi_rc_ != MPI_SUCCESS) return MpiError(sh_mpi_rc_, #call); \
  } while (0)

// MPI_COMM_WORLD with errors returned (not fatal), so they reach the caller as statuses
class MpiCommunicator final : public core::Communicator {
 public:
  MpiCommunicator() {
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
    received_.assign(size_, 0);
  }
  ~MpiCommunicator() override {
    for (Pending& p : pending_) MPI_Cancel(&p.request);
    MPI_Finalize();
  }
  MpiCommunicator(const MpiCommunicator&) = delete;
  MpiCommunicator& operator=(const MpiCommunicator&) = delete;

  int rank() const override { return rank_; }
  int size() const override { return size_; }
  std::string name() const override {
    char v[MPI_MAX_LIBRARY_VERSION_STRING];
    int len = 0;
    MPI_Get_library_version(v, &len);
    std::string s(v, len);
    return s.substr(0, s.find_first_of(",\n"));
  }
  // waits without spinning (MPI's blocking calls poll a core at 100 %), so a rank that is done
  // leaves its core to the ranks still working
  absl::Status Barrier() override {
    MPI_Request request;
    SH_MPI(MPI_Ibarrier(MPI_COMM_WORLD, &request));
    for (int done = 0; !done;) {
      SH_MPI(MPI_Test(&request, &done, MPI_STATUS_IGNORE));
      if (!done) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return absl::OkStatus();
  }
  absl::Status AllreduceSum(float* data, int64_t n) override {
    return Allreduce(data, n, MPI_FLOAT, sizeof(float));
  }
  absl::Status AllreduceSum(double* data, int64_t n) override {
    return Allreduce(data, n, MPI_DOUBLE, sizeof(double));
  }

  core::StatusOr<std::vector<std::string>> Gather(const std::string& blob, int root) override {
    int len = static_cast<int>(blob.size());
    std::vector<int> lens(rank_ == root ? size_ : 0), offsets(lens.size());
    SH_MPI(MPI_Gather(&len, 1, MPI_INT, lens.data(), 1, MPI_INT, root, MPI_COMM_WORLD));
    std::string all;
    if (rank_ == root) {
      int64_t total = 0;
      for (int r = 0; r < size_; ++r) {
        offsets[r] = static_cast<int>(total);
        total += lens[r];
      }
      if (total > INT32_MAX) return absl::ResourceExhaustedError("Gather of more than 2 GB");
      all.resize(total);
    }
    SH_MPI(MPI_Gatherv(blob.data(), len, MPI_CHAR, all.data(), lens.data(), offsets.data(),
                       MPI_CHAR, root, MPI_COMM_WORLD));
    std::vector<std::string> out;
    for (size_t r = 0; r < lens.size(); ++r) out.push_back(all.substr(offsets[r], lens[r]));
    return out;
  }

  absl::Status Broadcast(std::string* blob, int root) override {
    int64_t len = static_cast<int64_t>(blob->size());
    SH_MPI(MPI_Bcast(&len, 1, MPI_INT64_T, root, MPI_COMM_WORLD));
    blob->resize(len);
    SH_MPI(MPI_Bcast(blob->data(), static_cast<int>(len), MPI_CHAR, root, MPI_COMM_WORLD));
    return absl::OkStatus();
  }

  void PostToRoot(std::string message) override {
    if (rank_ == 0) return;
    pending_.push_back(Pending{std::move(message), MPI_REQUEST_NULL});
    Pending& p = pending_.back();
    MPI_Isend(p.bytes.data(), static_cast<int>(p.bytes.size()), MPI_CHAR, 0, kPostTag,
              MPI_COMM_WORLD, &p.request);
    ++posted_;
    // forget the sends that have completed
    for (auto it = pending_.begin(); it != pending_.end();) {
      int done = 0;
      MPI_Test(&it->request, &done, MPI_STATUS_IGNORE);
      it = done ? pending_.erase(it) : std::next(it);
    }
  }

  std::vector<std::pair<int, std::string>> Poll() override {
    std::vector<std::pair<int, std::string>> out;
    if (rank_ != 0) return out;
    while (true) {
      int flag = 0;
      MPI_Status st;
      if (MPI_Iprobe(MPI_ANY_SOURCE, kPostTag, MPI_COMM_WORLD, &flag, &st) != MPI_SUCCESS || !flag)
        break;
      out.push_back(Receive(st));
    }
    return out;
  }

  core::StatusOr<std::vector<std::pair<int, std::string>>> FinishPosts() override {
    int64_t mine = posted_;
    std::vector<int64_t> counts(rank_ == 0 ? size_ : 0);
    SH_MPI(MPI_Gather(&mine, 1, MPI_INT64_T, counts.data(), 1, MPI_INT64_T, 0, MPI_COMM_WORLD));
    std::vector<std::pair<int, std::string>> out;
    if (rank_ == 0) {
      for (int src = 1; src < size_; ++src) {
        while (received_[src] < counts[src]) {
          MPI_Status st;
          SH_MPI(MPI_Probe(src, kPostTag, MPI_COMM_WORLD, &st));
          out.push_back(Receive(st));
        }
      }
    }
    for (Pending& p : pending_) SH_MPI(MPI_Wait(&p.request, MPI_STATUS_IGNORE));
    pending_.clear();
    return out;
  }

 private:
  struct Pending {
    std::string bytes;
    MPI_Request request;
  };

  absl::Status Allreduce(void* data, int64_t n, MPI_Datatype type, size_t elem) {
    const auto t0 = std::chrono::steady_clock::now();
    SH_MPI(MPI_Allreduce(MPI_IN_PLACE, data, static_cast<int>(n), type, MPI_SUM, MPI_COMM_WORLD));
    stats_.allreduce_s +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ++stats_.allreduce_calls;
    stats_.allreduce_bytes += n * static_cast<int64_t>(elem);
    return absl::OkStatus();
  }

  std::pair<int, std::string> Receive(const MPI_Status& probed) {
    int len = 0;
    MPI_Get_count(&probed, MPI_CHAR, &len);
    std::string bytes(len, '\0');
    MPI_Recv(bytes.data(), len, MPI_CHAR, probed.MPI_SOURCE, kPostTag, MPI_COMM_WORLD,
             MPI_STATUS_IGNORE);
    ++received_[probed.MPI_SOURCE];
    return {probed.MPI_SOURCE, std::move(bytes)};
  }

  int rank_ = 0, size_ = 1;
  int64_t posted_ = 0;
  std::vector<int64_t> received_;
  std::list<Pending> pending_;
};

#endif  // SIMHUMAN_HAVE_MPI

}  // namespace

bool MpiBuilt() {
#ifdef SIMHUMAN_HAVE_MPI
  return true;
#else
  return false;
#endif
}

bool LaunchedByMpi() {
  for (const char* var : {"OMPI_COMM_WORLD_SIZE", "PMI_RANK", "PMIX_RANK"}) {
    if (std::getenv(var)) return true;
  }
  return false;
}

core::StatusOr<std::unique_ptr<core::Communicator>> StartCommunicator() {
  if (!LaunchedByMpi()) return std::unique_ptr<core::Communicator>(new core::SerialCommunicator);
#ifdef SIMHUMAN_HAVE_MPI
  int provided = 0;
  int rc = MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  if (rc != MPI_SUCCESS) return MpiError(rc, "MPI_Init_thread");
  return std::unique_ptr<core::Communicator>(new MpiCommunicator);
#else
  if (LauncherSize() > 1) {
    return absl::FailedPreconditionError(
        "started by an MPI launcher with " + std::to_string(LauncherSize()) +
        " ranks, but this simhuman was built without Open MPI (SIMHUMAN_MPI=OFF); rebuild with "
        "libopenmpi-dev installed, or run one process without mpirun");
  }
  return std::unique_ptr<core::Communicator>(new core::SerialCommunicator);
#endif
}

}  // namespace simhuman::dist
