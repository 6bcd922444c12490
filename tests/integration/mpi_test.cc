// `mpirun -n K simhuman eval|train` (issue 19), on this machine with --oversubscribe: the
// sharded eval writes what one process writes (apart from timing fields) for 1, 2 and 3
// ranks; a rank killed with SIGKILL loses no finished episode and --resume runs only the
// missing ones; bad jobs (more ranks than episodes, an unwritable folder, mismatched flags or
// binaries) end with a clear error and no hang; data-parallel training repeats with the same
// seed and rank count and resumes on another rank count. Skipped when built without MPI.

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <thread>

namespace {
namespace fs = std::filesystem;

const std::string kBin = SIMHUMAN_BIN;
// every command is cut after this long: a hang fails the test instead of blocking ctest
constexpr int kTimeoutS = 240;
// a cheap MPC so that an episode takes about a second (the results need not be good)
constexpr char kTinyMpc[] = R"({"samples": 4, "horizon_s": 0.2, "knots": 2, "threads": 1})";

struct Result {
  int exit_code = -1;
  std::string output;  // stdout and stderr
};

Result Shell(const std::string& command) {
  const std::string full = "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 timeout " +
                           std::to_string(kTimeoutS) + " sh -c '" + command + "' 2>&1";
  Result r;
  FILE* p = popen(full.c_str(), "r");
  if (!p) return r;
  char buf[4096];
  size_t n;
  while ((n = fread(buf, 1, sizeof(buf), p)) > 0) r.output.append(buf, n);
  int status = pclose(p);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

std::string Slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string Mpirun(int ranks) {
#ifdef SIMHUMAN_MPIRUN
  return std::string(SIMHUMAN_MPIRUN) + " --oversubscribe -n " + std::to_string(ranks) + " ";
#else
  (void)ranks;
  return "";
#endif
}

class MpiIntegrationTest : public ::testing::Test {
 protected:
  void SetUp() override {
#ifndef SIMHUMAN_MPIRUN
    GTEST_SKIP() << "built without Open MPI (SIMHUMAN_MPI=OFF)";
#endif
    dir_ = (fs::temp_directory_path() / ("simhuman_mpi_" + std::to_string(getpid()))).string();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    std::ofstream(dir_ + "/tiny.json") << kTinyMpc;
  }
  void TearDown() override {
    if (!dir_.empty()) fs::remove_all(dir_);
  }

  // the eval command line of the test suite (reach, tiny MPC) writing to dir_/<out>
  std::string Eval(const std::string& out, int episodes, const std::string& extra = "",
                   int seed = 3) const {
    return kBin + " eval --suite reach --seed " + std::to_string(seed) + " --episodes " +
           std::to_string(episodes) + " --config " + dir_ + "/tiny.json --out " + dir_ + "/" + out +
           " " + extra;
  }
  std::string Path(const std::string& name) const { return dir_ + "/" + name; }

  std::string dir_;
};

// the file with the values of its timing fields blanked out
std::string WithoutTiming(const std::string& path) {
  static const std::regex timing(R"re("(wall_time_s|wall_per_sim)": ?(null|[-+0-9.eE]+))re");
  return std::regex_replace(Slurp(path), timing, "\"$1\":T");
}

TEST_F(MpiIntegrationTest, EvalOnOneTwoThreeRanksWritesTheSameFiles) {
  Result one = Shell(Eval("r1", 4));
  ASSERT_EQ(one.exit_code, 0) << one.output;
  for (int k : {2, 3}) {
    const std::string out = "r" + std::to_string(k);
    Result r = Shell(Mpirun(k) + Eval(out, 4));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find(std::to_string(k) + " ranks"), std::string::npos) << r.output;
    for (const char* file : {"/episodes.jsonl", "/summary.json"}) {
      const std::string a = WithoutTiming(Path("r1") + file), b = WithoutTiming(Path(out) + file);
      EXPECT_FALSE(a.empty());
      EXPECT_EQ(a, b) << file << " differs with " << k << " ranks";
    }
    // the journals of the other ranks are folded in and removed
    EXPECT_FALSE(fs::exists(Path(out) + "/episodes.rank1.jsonl"));
  }
}

// the pid of rank `rank` of the job whose command line mentions `marker`, or 0
pid_t FindRank(int rank, const std::string& marker) {
  const std::string want = "OMPI_COMM_WORLD_RANK=" + std::to_string(rank);
  for (const fs::directory_entry& e : fs::directory_iterator("/proc")) {
    const std::string name = e.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::string cmd = Slurp(e.path().string() + "/cmdline");
    std::string env = Slurp(e.path().string() + "/environ");
    for (char& c : env) c = c ? c : '\n';
    if (cmd.find(marker) != std::string::npos && cmd.find("mpirun") == std::string::npos &&
        (env.find("\n" + want + "\n") != std::string::npos || env.rfind(want + "\n", 0) == 0)) {
      return static_cast<pid_t>(std::stoi(name));
    }
  }
  return 0;
}

int Lines(const std::string& path) {
  std::ifstream in(path);
  int n = 0;
  for (std::string line; std::getline(in, line);) n += !line.empty();
  return n;
}

TEST_F(MpiIntegrationTest, EvalRankKilledKeepsFinishedEpisodesAndResumes) {
  Result ref = Shell(Eval("ref", 6));
  ASSERT_EQ(ref.exit_code, 0) << ref.output;
  Result killed_run;
  std::thread job([&] { killed_run = Shell(Mpirun(2) + Eval("killed", 6)); });
  // once rank 1 has finished an episode, kill it
  const std::string journal = Path("killed") + "/episodes.rank1.jsonl";
  pid_t victim = 0;
  for (int i = 0; i < 2000 && victim == 0; ++i) {
    if (Lines(journal) >= 1) victim = FindRank(1, Path("killed"));
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ASSERT_NE(victim, 0) << "rank 1 never finished an episode";
  kill(victim, SIGKILL);
  job.join();
  EXPECT_NE(killed_run.exit_code, 0) << killed_run.output;
  const int kept = Lines(Path("killed") + "/episodes.jsonl") + Lines(journal);
  EXPECT_GE(Lines(journal), 1);
  ASSERT_LT(kept, 6) << "the job finished before the kill";

  // --resume names the missing episodes and runs only those (here on 2 ranks again)
  Result resumed = Shell(Mpirun(2) + Eval("killed", 6, "--resume"));
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("resuming: " + std::to_string(kept) + " of 6 episodes finished"),
            std::string::npos)
      << resumed.output;
  EXPECT_NE(resumed.output.find("missing (to run now): "), std::string::npos);
  for (const char* file : {"/episodes.jsonl", "/summary.json"}) {
    EXPECT_EQ(WithoutTiming(Path("ref") + file), WithoutTiming(Path("killed") + file)) << file;
  }
  // a second --resume has nothing left to run
  Result again = Shell(Eval("killed", 6, "--resume"));
  EXPECT_EQ(again.exit_code, 0) << again.output;
  EXPECT_NE(again.output.find("missing (to run now): none"), std::string::npos) << again.output;
}

TEST_F(MpiIntegrationTest, EvalBadJobsFailClearlyWithoutHanging) {
  // more ranks than episodes
  Result r = Shell(Mpirun(3) + Eval("few", 2));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("--episodes 2 is fewer than the 3 ranks"), std::string::npos) << r.output;
  // an output folder that cannot be made on rank 0
  std::ofstream(Path("file")) << "x";
  r = Shell(Mpirun(2) + kBin + " eval --suite reach --episodes 2 --out " + Path("file/out"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("cannot create output directory '" + Path("file/out") + "'"),
            std::string::npos)
      << r.output;
  // ranks started with different flags
  r = Shell(Mpirun(1) + Eval("mixed", 2) + " : -n 1 " + Eval("mixed", 2, "", 4));
  EXPECT_NE(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("mismatched eval options across ranks: rank 0 has"), std::string::npos)
      << r.output;
  // ranks started from different binaries
  fs::copy_file(kBin, Path("other_simhuman"));
  std::ofstream(Path("other_simhuman"), std::ios::app) << "another build";
  r = Shell(Mpirun(1) + Eval("bins", 2) + " : -n 1 " + Path("other_simhuman") + " eval --suite " +
            "reach --seed 3 --episodes 2 --config " + Path("tiny.json") + " --out " + Path("bins"));
  EXPECT_NE(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("mismatched simhuman binaries across ranks"), std::string::npos)
      << r.output;
}

TEST_F(MpiIntegrationTest, EvalResumeOfAnotherRunIsRefused) {
  Result r = Shell(Eval("run", 2));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = Shell(Eval("run", 2, "--resume", 5));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("the run being resumed has seed 3 but this one has 5"), std::string::npos)
      << r.output;
  r = Shell(Eval("none", 2, "--resume"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("nothing to resume"), std::string::npos) << r.output;
}

TEST_F(MpiIntegrationTest, TrainRepeatsWithSameSeedAndRanksAndResumesOnOtherRanks) {
  auto train = [&](const std::string& out) {
    return Shell(Mpirun(2) + kBin + " train --task reach --steps 12k --envs 16 --threads 1 " +
                 "--quiet --out " + Path(out));
  };
  Result a = train("a");
  ASSERT_EQ(a.exit_code, 0) << a.output;
  EXPECT_NE(a.output.find("x 2 ranks"), std::string::npos) << a.output;
  Result b = train("b");
  ASSERT_EQ(b.exit_code, 0) << b.output;
  const std::string pa = Slurp(Path("a/policy.pt")), pb = Slurp(Path("b/policy.pt"));
  EXPECT_FALSE(pa.empty());
  EXPECT_TRUE(pa == pb) << "same seed and ranks gave different weights";
  // rank 0 alone writes the log, with the allreduce cost
  const std::string log = Slurp(Path("a/log.jsonl"));
  EXPECT_NE(log.find("\"ranks\":2"), std::string::npos);
  EXPECT_NE(log.find("\"allreduce_bytes\""), std::string::npos);
  // and every rank's own rollout time, both positive (the scaling model's spread)
  {
    std::istringstream lines(log);
    std::string first;
    std::getline(lines, first);
    nlohmann::json j = nlohmann::json::parse(first);
    ASSERT_TRUE(j.contains("rank_rollout_s")) << first;
    ASSERT_EQ(j["rank_rollout_s"].size(), 2u) << first;
    for (const auto& t : j["rank_rollout_s"]) EXPECT_GT(t.get<double>(), 0.0) << first;
  }
  // resumed on one rank, then on three
  Result one = Shell(kBin + " train --resume " + Path("a") + " --steps 16k --quiet");
  ASSERT_EQ(one.exit_code, 0) << one.output;
  Result three = Shell(Mpirun(3) + kBin + " train --resume " + Path("a") + " --steps 20k --quiet");
  ASSERT_EQ(three.exit_code, 0) << three.output;
  EXPECT_NE(three.output.find("done, 20"), std::string::npos) << three.output;
  EXPECT_NE(Slurp(Path("a/log.jsonl")).find("\"ranks\":3"), std::string::npos);
}

}  // namespace
