// Every input the fuzzers (fuzz/, scripts/fuzz) or issue 13 found to crash
// the binary, kept in tests/fuzz_regressions/, goes through the real command:
// each must be accepted (exit 0) or refused in one line `bestiary: ...` with
// exit code 2: never a signal, never several lines, never a hang.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "../../fuzz/fuzz_input.h"
#include "support/run_command.h"

namespace bxtest {
namespace {

constexpr int kTimeoutSeconds = 30;

/// What a command did: exit code (or -signal, or 0 with timed_out), its error output.
struct Ran {
  int code = 0;
  bool signalled = false, timed_out = false;
  std::string err, out;
  double seconds = 0;
};

// Runs BESTIARY_BINARY with these arguments exactly (no shell: an argument
// may hold a newline), killing it after kTimeoutSeconds.
Ran run_bestiary(const std::vector<std::string>& args, const fs::path& dir) {
  fs::path out_file = dir / "stdout.txt", err_file = dir / "stderr.txt";
  auto start = std::chrono::steady_clock::now();
  pid_t pid = ::fork();
  if (pid == 0) {
    FILE* o = std::freopen(out_file.c_str(), "w", stdout);
    FILE* e = std::freopen(err_file.c_str(), "w", stderr);
    if (!o || !e) ::_exit(127);
    std::vector<char*> argv{const_cast<char*>(BESTIARY_BINARY)};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(BESTIARY_BINARY, argv.data());
    ::_exit(127);
  }
  Ran r;
  int status = 0;
  while (::waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() - start > std::chrono::seconds(kTimeoutSeconds)) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      r.timed_out = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.signalled = WIFSIGNALED(status);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
  r.err = slurp(err_file);
  r.out = slurp(out_file);
  return r;
}

// Accepted, or refused in one line with exit code 2.
void expect_outcome(const Ran& r, const std::string& what) {
  EXPECT_FALSE(r.timed_out) << what << ": still running after " << kTimeoutSeconds << " s";
  EXPECT_FALSE(r.signalled) << what << ": killed by signal " << -r.code << "\n" << r.err;
  if (r.timed_out || r.signalled) return;
  EXPECT_TRUE(r.code == 0 || r.code == 2) << what << ": exit code " << r.code << "\n" << r.err;
  if (r.code == 2) {
    EXPECT_EQ(count_lines(r.err), 1) << what << ": not one line:\n" << r.err;
    EXPECT_EQ(r.err.rfind("bestiary: ", 0), 0u) << what << ": " << r.err;
  }
}

// a regression file: the text, then any `--set` overrides, each after a NUL,
// split as the fuzz targets split their input
using bxfuzz::Input;
using bxfuzz::split;
Input read_input(const fs::path& p) {
  std::string all = slurp(p);
  return split(reinterpret_cast<const std::uint8_t*>(all.data()), all.size());
}

std::vector<fs::path> regressions(const std::string& kind) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(fs::path(BESTIARY_SOURCE_DIR) / "tests/fuzz_regressions" / kind))
    if (e.is_regular_file()) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

class FuzzRegressions : public InTempDir {};

TEST_F(FuzzRegressions, GenomesAreSimulatedOrRefusedInOneLine) {
  auto files = regressions("genome");
  ASSERT_GE(files.size(), 10u);
  for (const auto& f : files) {
    Input in = read_input(f);
    fs::path genome = dir / f.filename();
    genome.replace_extension(".json");
    std::ofstream(genome, std::ios::binary) << in.text;
    // as the genome fuzz target runs it: its develop.* overrides, 0.3 s
    std::vector<std::string> sets;
    for (const auto& o : in.overrides)
      if (o.rfind("develop.", 0) == 0) sets.insert(sets.end(), {"--set", o});
    std::vector<std::string> args{"simulate", genome.string(), "--seconds", "0.3"};
    args.insert(args.end(), sets.begin(), sets.end());
    expect_outcome(run_bestiary(args, dir), "simulate " + f.filename().string());
    // `show` printed the same errors (and crashed on the same nesting)
    args = {"show", genome.string(), "--seconds", "0.3", "--out", (dir / "view.html").string()};
    args.insert(args.end(), sets.begin(), sets.end());
    expect_outcome(run_bestiary(args, dir), "show " + f.filename().string());
  }
}

TEST_F(FuzzRegressions, ConfigsAreReadOrRefusedInOneLine) {
  auto files = regressions("config");
  ASSERT_GE(files.size(), 5u);
  std::string box = creature("box.json");
  for (const auto& f : files) {
    Input in = read_input(f);
    fs::path config = dir / f.filename();
    config.replace_extension(".toml");
    std::ofstream(config, std::ios::binary) << in.text;
    expect_outcome(run_bestiary({"config", "--config", config.string()}, dir), "config " + f.filename().string());
    // the run config reader (`run`, `resume`, `simulate --config`), with the overrides
    std::vector<std::string> args{"simulate", box, "--config", config.string(), "--seconds", "0.3"};
    for (const auto& o : in.overrides) args.insert(args.end(), {"--set", o});
    expect_outcome(run_bestiary(args, dir), "simulate --config " + f.filename().string());
  }
}

// The newline that set another key (issue 13): refused, and says why
TEST_F(FuzzRegressions, ANewlineInASetValueIsRefused) {
  Ran r = run_bestiary({"simulate", creature("box.json"), "--seconds", "0.1", "--set", "task.seconds=1\nphysics.gravity=5"}, dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err,
            "bestiary: --set: a control character (newline, tab, ...) in \"task.seconds=1\\nphysics.gravity=5\" "
            "(one section.key=value per --set)\n");
}

// 300,000 neurons (9 MB) took 12.5 s to parse, quadratic in the array's
// length; generated here rather than kept in the tree. The time is printed,
// not judged (the timeout above is the bound).
TEST_F(FuzzRegressions, A300000NeuronGenomeIsSimulated) {
  std::string neurons;
  for (int i = 0; i < 300000; ++i) neurons += std::string(i ? "," : "") + R"({"fn": "sum", "inputs": []})";
  fs::path genome = dir / "neurons.json";
  std::ofstream(genome) << R"({"format": "bestiary-genome", "version": 1, "dialect": "sims1994",
    "nodes": [{"size": [0.4, 0.4, 0.4]}], "global_neurons": [)" << neurons << "]}";
  Ran r = run_bestiary({"simulate", genome.string(), "--seconds", "0.01"}, dir);
  expect_outcome(r, "simulate neurons.json");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("300000 neurons"), std::string::npos) << r.out;
  std::printf("300,000-neuron genome: read, developed and simulated (0.01 s) in %.2f s\n", r.seconds);
}

}  // namespace
}  // namespace bxtest
