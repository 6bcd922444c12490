#include "simhuman/core/communicator.h"

#include <cstdio>
#include <fstream>

namespace simhuman::core {

Status SerialCommunicator::AllreduceSum(float*, int64_t n) {
  ++stats_.allreduce_calls;
  stats_.allreduce_bytes += n * static_cast<int64_t>(sizeof(float));
  return absl::OkStatus();
}

Status SerialCommunicator::AllreduceSum(double*, int64_t n) {
  ++stats_.allreduce_calls;
  stats_.allreduce_bytes += n * static_cast<int64_t>(sizeof(double));
  return absl::OkStatus();
}

StatusOr<std::vector<std::string>> SerialCommunicator::Gather(const std::string& blob, int root) {
  if (root != 0) {
    return absl::InvalidArgumentError("Gather root " + std::to_string(root) +
                                      " is invalid; valid: 0 (one rank)");
  }
  return std::vector<std::string>{blob};
}

Status SerialCommunicator::Broadcast(std::string*, int root) {
  if (root != 0) {
    return absl::InvalidArgumentError("Broadcast root " + std::to_string(root) +
                                      " is invalid; valid: 0 (one rank)");
  }
  return absl::OkStatus();
}

Status AgreeOk(Communicator& comm, const Status& local) {
  if (comm.size() == 1) return local;
  // every rank's verdict to rank 0, which picks the lowest failing rank and tells everyone
  const std::string mine = local.ok() ? std::string()
                                      : std::to_string(static_cast<int>(local.code())) + "\n" +
                                            std::to_string(comm.rank()) + "\n" +
                                            std::string(local.message());
  SH_ASSIGN_OR_RETURN(std::vector<std::string> all, comm.Gather(mine, 0));
  std::string verdict;
  for (const std::string& v : all) {
    if (!v.empty()) {
      verdict = v;
      break;
    }
  }
  SH_RETURN_IF_ERROR(comm.Broadcast(&verdict, 0));
  if (verdict.empty()) return absl::OkStatus();
  const size_t a = verdict.find('\n'), b = verdict.find('\n', a + 1);
  const int code = std::stoi(verdict.substr(0, a));
  const std::string rank = verdict.substr(a + 1, b - a - 1);
  return Status(static_cast<absl::StatusCode>(code), "rank " + rank + ": " + verdict.substr(b + 1));
}

Status CheckSameOnAllRanks(Communicator& comm, const std::string& what, const std::string& value) {
  if (comm.size() == 1) return absl::OkStatus();
  SH_ASSIGN_OR_RETURN(std::vector<std::string> hashes, comm.Gather(HashHex(value), 0));
  std::string verdict;
  for (size_t r = 1; r < hashes.size(); ++r) {
    if (hashes[r] == hashes[0]) continue;
    verdict += (verdict.empty() ? "" : ", ") + std::string("rank ") + std::to_string(r) + " has " +
               hashes[r];
  }
  if (!verdict.empty()) {
    verdict = "mismatched " + what + " across ranks: rank 0 has " + hashes[0] + ", " + verdict +
              "; start every rank with the same binary and the same flags and files";
  }
  SH_RETURN_IF_ERROR(comm.Broadcast(&verdict, 0));
  if (verdict.empty()) return absl::OkStatus();
  return absl::InvalidArgumentError(verdict);
}

std::string HashHex(const std::string& bytes) {
  uint64_t h = 14695981039346656037ull;
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ull;
  }
  char buf[17];
  std::snprintf(buf, sizeof(buf), "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

StatusOr<std::string> FileHashHex(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) return absl::NotFoundError(path + ": cannot read the file to hash it");
  std::string bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  return HashHex(bytes);
}

}  // namespace simhuman::core
