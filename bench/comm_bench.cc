// The cost of one gradient allreduce between ranks on this machine, without waits for slower
// ranks: `mpirun -n K build/simhuman_comm_bench [FLOATS [REPEATS]]` times REPEATS back-to-back
// AllreduceSum calls of FLOATS floats (default: the walk policy's actor and critic, 70,000
// floats) after a barrier and prints, on rank 0, the mean time per call and the bytes.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "simhuman/dist/mpi_communicator.h"

int main(int argc, char** argv) {
  using Clock = std::chrono::steady_clock;
  const long floats = argc > 1 ? std::atol(argv[1]) : 70000;
  const int repeats = argc > 2 ? std::atoi(argv[2]) : 200;
  if (floats < 1 || repeats < 1) {
    std::fprintf(stderr, "usage: simhuman_comm_bench [FLOATS >= 1 [REPEATS >= 1]]\n");
    return 2;
  }
  auto comm = simhuman::dist::StartCommunicator();
  if (!comm.ok()) {
    std::fprintf(stderr, "simhuman_comm_bench: %s\n", std::string(comm.status().message()).c_str());
    return 1;
  }
  simhuman::core::Communicator& c = **comm;
  std::vector<float> buf(static_cast<size_t>(floats), 1.f);
  // warm-up, then the timed calls
  for (int i = 0; i < 10; ++i) (void)c.AllreduceSum(buf.data(), floats);
  (void)c.Barrier();
  const auto t0 = Clock::now();
  for (int i = 0; i < repeats; ++i) {
    if (!c.AllreduceSum(buf.data(), floats).ok()) return 1;
  }
  const double s = std::chrono::duration<double>(Clock::now() - t0).count() / repeats;
  if (c.rank() == 0) {
    std::printf(
        "ranks %d (%s), %ld floats (%ld bytes) per allreduce: %.1f us per call, %.2f GB/s\n",
        c.size(), c.name().c_str(), floats, floats * 4, 1e6 * s, floats * 4 / s / 1e9);
  }
  return 0;
}
