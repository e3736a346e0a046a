#include "cluster/mpi_evaluator.h"

#include <mpi.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "eval/records_json.h"
#include "io/config.h"
#include "run/run.h"

namespace bx {

namespace {

using nlohmann::json;

// message tags: rank 0 -> a worker rank (table, job, stop); a worker -> rank 0 (result)
constexpr int kTable = 1, kJob = 2, kResult = 3, kStop = 4;

bool g_started = false;   // MPI_Init done by mpi_start
bool g_stopped = false;   // the worker ranks told to stop
// this process's group (`run --seeds`: one group of ranks per seed, each its
// own rank 0 and evaluators; otherwise one group, the world), its rank and size in it
MPI_Comm g_comm = MPI_COMM_NULL;
int g_rank = 0, g_size = 1, g_group = 0, g_groups = 1;

// Waits for a message without spinning a core: an MPI implementation's
// blocking receive polls flat out, which on an oversubscribed node takes the
// core a rank's evaluation needs. Probes with a sleep growing to 0.2 ms, so a
// message waits at most about 0.2 ms (bench_mpi: 1 ms longer a job than the pool).
MPI_Status wait_message(int source, int tag) {
  MPI_Status st;
  int flag = 0;
  useconds_t nap = 0;
  for (;;) {
    MPI_Iprobe(source, tag, g_comm, &flag, &st);
    if (flag) return st;
    nap = std::min<useconds_t>(nap * 2 + 10, 200);
    ::usleep(nap);
  }
}

std::string receive_text(const MPI_Status& st) {
  int n = 0;
  MPI_Get_count(&st, MPI_CHAR, &n);
  std::string s(static_cast<std::size_t>(n), '\0');
  MPI_Recv(s.data(), n, MPI_CHAR, st.MPI_SOURCE, st.MPI_TAG, g_comm, MPI_STATUS_IGNORE);
  return s;
}

void send_text(const std::string& s, int dest, int tag) {
  if (s.size() > static_cast<std::size_t>(INT32_MAX)) throw std::length_error("MPI message over 2 GiB");
  MPI_Send(s.data(), static_cast<int>(s.size()), MPI_CHAR, dest, tag, g_comm);
}

// a task's config back from the TOML text config_to_toml wrote
Result<SimConfig> sim_from_toml(const std::string& text, int task) {
  RunConfig rc;
  if (Status s = apply_config_toml(rc, text, "task " + std::to_string(task) + " of the task table"); !s)
    return Error{s.error()};
  return rc.sim;
}

// rank 0 ends: every worker rank stops, then MPI ends (at exit, however the command ends)
void stop_ranks() {
  if (!g_started || g_rank != 0 || g_stopped) return;
  g_stopped = true;
  for (int r = 1; r < g_size; ++r) send_text("", r, kStop);
  MPI_Finalize();
}

// a worker rank's life: tables and jobs from rank 0, answered one by one, until told to stop
int serve() {
  std::unique_ptr<ProcessPoolEvaluator> pool;
  std::string table_error = "no task table received";
  for (;;) {
    const MPI_Status st = wait_message(0, MPI_ANY_TAG);
    const std::string msg = receive_text(st);
    if (st.MPI_TAG == kStop) break;
    if (st.MPI_TAG == kTable) {
      pool.reset();
      const json t = json::parse(msg, nullptr, false);
      std::vector<SimConfig> tasks;
      table_error.clear();
      if (!t.is_object() || !t.contains("tasks") || !t["tasks"].is_array() || !t.contains("timeout")) {
        table_error = "unreadable task table";
      } else {
        for (std::size_t k = 0; k < t["tasks"].size() && table_error.empty(); ++k) {
          auto c = sim_from_toml(t["tasks"][k].get<std::string>(), static_cast<int>(k));
          if (c) tasks.push_back(std::move(*c));
          else table_error = c.error();
        }
      }
      // one forked child evaluates: a crash or a hang costs that evaluation
      // (given again once on a fresh child, as in the pool), never this rank
      if (table_error.empty()) pool = std::make_unique<ProcessPoolEvaluator>(tasks, 1, t["timeout"].get<double>());
      continue;
    }
    EvalOutcome o;
    auto job = job_from_json(json::parse(msg, nullptr, false));
    if (!pool) {
      o.result.failed = true;
      o.result.failure = "rank " + std::to_string(g_rank) + ": " + table_error;
    } else if (!job) {
      o.result.failed = true;
      o.result.failure = "rank " + std::to_string(g_rank) + " could not read its job: " + job.error();
    } else {
      o = pool->evaluate({EvalJob{job->genotype.get(), job->seed, job->step_divisor, job->task}}).front();
    }
    send_text(outcome_to_json(o).dump(), 0, kResult);
  }
  pool.reset();
  MPI_Finalize();
  return 0;
}

class MpiEvaluator : public Evaluator {
 public:
  explicit MpiEvaluator(int ranks) : ranks_(ranks) {}

  std::vector<EvalOutcome> evaluate(const std::vector<EvalJob>& jobs) override {
    std::vector<EvalOutcome> out(jobs.size());
    // longest first, as the pool hands them out; results come back in job order
    const std::vector<int> order = longest_first(jobs);
    std::deque<int> pending(order.begin(), order.end());
    std::vector<int> working(static_cast<std::size_t>(ranks_ + 1), -1);  // by rank: its job, or -1
    std::size_t done = 0;
    while (done < jobs.size()) {
      for (int r = 1; r <= ranks_ && !pending.empty(); ++r) {
        if (working[r] >= 0) continue;
        working[r] = pending.front();
        pending.pop_front();
        send_text(job_to_json(jobs[working[r]]).dump(), r, kJob);
      }
      const MPI_Status st = wait_message(MPI_ANY_SOURCE, kResult);
      const std::string msg = receive_text(st);
      const int j = working[st.MPI_SOURCE];
      working[st.MPI_SOURCE] = -1;
      auto o = outcome_from_json(json::parse(msg, nullptr, false));
      if (o) {
        out[j] = std::move(*o);
      } else {  // not expected: every rank runs this program's serialiser
        out[j].result.failed = true;
        out[j].result.failure = "rank " + std::to_string(st.MPI_SOURCE) + " sent an unreadable result (" + o.error() + ")";
      }
      ++done;
    }
    return out;
  }

  int workers() const override { return ranks_; }

 private:
  int ranks_;
};

}  // namespace

bool mpi_requested(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--evaluator=mpi") == 0) return true;
    if (std::strcmp(argv[i], "--evaluator") == 0 && i + 1 < argc && std::strcmp(argv[i + 1], "mpi") == 0) return true;
  }
  return false;
}

std::optional<int> mpi_start(int* argc, char*** argv) {
  MPI_Init(argc, argv);
  g_started = true;
  int world_rank = 0, world_size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &world_rank);
  MPI_Comm_size(MPI_COMM_WORLD, &world_size);
  // `run --seeds`: the world in one group of consecutive ranks per seed (sizes
  // differing by at most one), each running its seed's run; a list the
  // command refuses leaves one group, and the command says why
  for (int i = 1; i < *argc; ++i) {
    std::string list;
    if (std::strcmp((*argv)[i], "--seeds") == 0 && i + 1 < *argc) list = (*argv)[i + 1];
    else if (std::strncmp((*argv)[i], "--seeds=", 8) == 0) list = (*argv)[i] + 8;
    else continue;
    if (auto seeds = parse_seed_list(list); seeds && seeds->size() <= static_cast<std::size_t>(world_size / 2))
      g_groups = static_cast<int>(seeds->size());
    break;
  }
  g_group = static_cast<int>(static_cast<long>(world_rank) * g_groups / world_size);
  MPI_Comm_split(MPI_COMM_WORLD, g_group, world_rank, &g_comm);
  MPI_Comm_rank(g_comm, &g_rank);
  MPI_Comm_size(g_comm, &g_size);
  if (g_rank != 0) return serve();
  std::atexit(stop_ranks);
  return std::nullopt;
}

int mpi_evaluating_ranks() { return g_started && g_rank == 0 ? g_size - 1 : 0; }

int mpi_group() { return g_group; }

int mpi_groups() { return g_groups; }

int mpi_world_size() {
  int n = 1;
  if (g_started) MPI_Comm_size(MPI_COMM_WORLD, &n);
  return n;
}

Status mpi_ready() {
  if (!g_started)
    return Error{"--evaluator mpi: MPI was not started (the command line must say --evaluator mpi)"};
  if (g_size < 2)
    return Error{"--evaluator mpi: this is the only MPI process, so none is left to evaluate; start it as "
                 "`mpirun -np N ...` with N of 2 or more (rank 0 runs the algorithm, the others evaluate)"};
  return Ok{};
}

Result<std::unique_ptr<Evaluator>> make_mpi_evaluator(const std::vector<SimConfig>& tasks, double timeout_seconds) {
  if (Status s = mpi_ready(); !s) return Error{s.error()};
  json table;
  table["timeout"] = timeout_seconds;
  table["tasks"] = json::array();
  for (int k = 0; k < static_cast<int>(tasks.size()); ++k) {
    std::string text = config_to_toml(tasks[k]);
    // every rank must evaluate exactly the config this one has
    auto back = sim_from_toml(text, k);
    if (!back) return Error{"--evaluator mpi: " + back.error()};
    if (!(*back == tasks[k]))
      return Error{"--evaluator mpi: task " + std::to_string(k) +
                   "'s config does not survive its trip to the other ranks as TOML text (a bug: please report it)"};
    table["tasks"].push_back(std::move(text));
  }
  const std::string msg = table.dump();
  for (int r = 1; r < g_size; ++r) send_text(msg, r, kTable);
  return std::unique_ptr<Evaluator>(std::make_unique<MpiEvaluator>(g_size - 1));
}

}  // namespace bx
