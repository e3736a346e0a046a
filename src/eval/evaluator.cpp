#include "eval/evaluator.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <stdexcept>
#include <nlohmann/json.hpp>
#include <thread>

#include "develop/develop.h"
#include "eval/records_json.h"
#include "genome/graph_genotype.h"

namespace bx {

EvalOutcome evaluate_genome(const Genome& g, const SimConfig& cfg, std::uint64_t seed) {
  EvalOutcome out;
  Development dev = develop(g, cfg.develop);
  if (!dev.viable()) {
    out.viable = false;
    out.reason = dev.reason;
    return out;
  }
  out.result = evaluate(*dev.model, cfg, seed);
  return out;
}

EvalOutcome evaluate_genotype(const Genotype& g, const SimConfig& cfg, std::uint64_t seed) {
  EvalOutcome out;
  // a kind without a body evaluates its genotype itself, with no world
  const CreatureKindRow& row = creature_kind_row(cfg.creature);
  if (row.evaluate) {
    Status s = g.kind() == row.genotype_kind
                   ? row.evaluate(g, cfg, seed, out.result)
                   : Status(Error{"a genotype of kind " + std::string(g.kind()) + ", but genotype.kind \"" +
                                  std::string(row.name) + "\" evaluates " + std::string(row.genotype_kind) +
                                  " genotypes"});
    if (!s) {
      out.viable = false;
      out.reason = s.error();
      out.result = EvalResult{};
    }
    return out;
  }
  auto creature = develop_creature(g, cfg);
  if (!creature) {
    out.viable = false;
    out.reason = creature.error();
    return out;
  }
  out.result = evaluate(*creature, cfg, seed);
  return out;
}

double repeated_genotype_fitness(const Genotype& g, const SimConfig& cfg, std::uint64_t seed, const Repeats& r,
                                 const EvalOutcome& first, std::vector<double>* each) {
  auto scored = [&](const EvalOutcome& o) { return !o.viable || o.result.failed ? r.failed_fitness : o.result.fitness; };
  const DividedSteps steps(cfg);
  double score = scored(first);
  if (each) each->assign(1, score);
  for (int k = 1; k < r.evaluations; ++k) {
    const double f = scored(evaluate_genotype(g, steps.at(repeat_step_divisor(r, k)), repeat_seed(seed, k)));
    if (each) each->push_back(f);
    score = fold_score(cfg.trial_score, score, k, f);
  }
  return score;
}

std::vector<int> longest_first(const std::vector<EvalJob>& jobs) {
  std::vector<int> order(jobs.size());
  std::vector<double> cost(jobs.size());
  for (int i = 0; i < static_cast<int>(jobs.size()); ++i) {
    order[i] = i;
    cost[i] = jobs[i].genotype->cost_hint();
  }
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return cost[a] > cost[b]; });
  return order;
}

SerialEvaluator::SerialEvaluator(const std::vector<SimConfig>& tasks) {
  for (const SimConfig& c : tasks) steps_.emplace_back(c);
}

std::vector<EvalOutcome> SerialEvaluator::evaluate(const std::vector<EvalJob>& jobs) {
  std::vector<EvalOutcome> out;
  out.reserve(jobs.size());
  for (const auto& j : jobs) {
    if (j.task < 0 || j.task >= static_cast<int>(steps_.size()))
      throw std::logic_error("evaluation job of task " + std::to_string(j.task) + " given to an evaluator of " +
                             std::to_string(steps_.size()));
    out.push_back(evaluate_genotype(*j.genotype, steps_[j.task].at(j.step_divisor), j.seed));
  }
  return out;
}

namespace {

using nlohmann::json;

// length-prefixed messages over pipes
bool write_all(int fd, const void* data, std::size_t n) {
  auto* p = static_cast<const char*>(data);
  while (n > 0) {
    ssize_t w = ::write(fd, p, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    p += w;
    n -= static_cast<std::size_t>(w);
  }
  return true;
}

bool read_all(int fd, void* data, std::size_t n) {
  auto* p = static_cast<char*>(data);
  while (n > 0) {
    ssize_t r = ::read(fd, p, n);
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) return false;
    p += r;
    n -= static_cast<std::size_t>(r);
  }
  return true;
}

bool send_message(int fd, const std::string& s) {
  auto n = static_cast<std::uint32_t>(s.size());
  return write_all(fd, &n, sizeof n) && write_all(fd, s.data(), s.size());
}

bool receive_message(int fd, std::string& s) {
  std::uint32_t n = 0;
  if (!read_all(fd, &n, sizeof n)) return false;
  s.resize(n);
  return read_all(fd, s.data(), n);
}

// the worker's life: read a job, evaluate it, answer; until the pipe closes
[[noreturn]] void worker_main(int in, int out, const std::vector<SimConfig>& tasks, const WorkerJob& work) {
  std::vector<DividedSteps> steps;
  for (const SimConfig& c : tasks) steps.emplace_back(c);
  std::string msg;
  while (receive_message(in, msg)) {
    // text that is not JSON parses to a discarded value, which the reader refuses
    auto job = job_from_json(json::parse(msg, nullptr, false));
    EvalOutcome o;
    if (!job) {
      o.result.failed = true;
      o.result.failure = "worker could not read its job: " + job.error();
    } else if (job->task >= static_cast<int>(steps.size())) {
      o.result.failed = true;
      o.result.failure = "worker has no task " + std::to_string(job->task) + " (it has " +
                         std::to_string(steps.size()) + ")";
    } else {
      o = work(*job->genotype, steps[job->task].at(job->step_divisor), job->seed);
    }
    if (!send_message(out, outcome_to_json(o).dump())) break;
  }
  ::_exit(0);
}

}  // namespace

struct ProcessPoolEvaluator::Impl {
  struct Worker {
    pid_t pid = -1;
    int to = -1, from = -1;  // pipe ends: jobs out, results in
    int job = -1;            // index of the job it is working on, or -1
    std::chrono::steady_clock::time_point deadline;
  };

  std::vector<SimConfig> tasks;
  WorkerJob work;
  double timeout;
  std::vector<Worker> workers;

  void spawn(Worker& w) {
    int jobs[2], results[2];
    if (::pipe(jobs) != 0 || ::pipe(results) != 0) throw std::runtime_error("pipe failed");
    const pid_t parent = ::getpid();
    // INT and TERM held back until the child has its own dispositions: a
    // signal in between would run the parent's handler in the child
    sigset_t stop, was;
    sigemptyset(&stop);
    sigaddset(&stop, SIGINT);
    sigaddset(&stop, SIGTERM);
    ::sigprocmask(SIG_BLOCK, &stop, &was);
    pid_t pid = ::fork();
    if (pid != 0) ::sigprocmask(SIG_SETMASK, &was, nullptr);
    if (pid < 0) throw std::runtime_error("fork failed");
    if (pid == 0) {
      // the child keeps stdio and its own two ends only: no other pool's pipes
      // (whose workers would then never see end-of-file) and no run database
      int in = jobs[0], out = results[1];
      int lo = std::min(in, out), hi = std::max(in, out);
      ::close_range(3, lo - 1, 0);
      ::close_range(lo + 1, hi - 1, 0);
      ::close_range(hi + 1, ~0U, 0);
      // the parent's handlers are not the worker's: Ctrl-C or a TERM to the
      // process group stops the parent, which says so once, and workers die
      // with it (at once, not after their evaluation)
      std::signal(SIGINT, SIG_IGN);
      std::signal(SIGTERM, SIG_IGN);  // (which also drops any held back)
      ::sigprocmask(SIG_SETMASK, &was, nullptr);
      ::prctl(PR_SET_PDEATHSIG, SIGKILL);
      if (::getppid() != parent) ::_exit(0);  // the parent died before prctl
      worker_main(in, out, tasks, work);
    }
    ::close(jobs[0]);
    ::close(results[1]);
    ::fcntl(jobs[1], F_SETFD, FD_CLOEXEC);
    ::fcntl(results[0], F_SETFD, FD_CLOEXEC);
    w.pid = pid;
    w.to = jobs[1];
    w.from = results[0];
    w.job = -1;
  }

  // ends a worker (killing it if need be) and says how it ended
  std::string reap(Worker& w, bool kill) {
    if (kill) ::kill(w.pid, SIGKILL);
    ::close(w.to);
    ::close(w.from);
    int status = 0;
    ::waitpid(w.pid, &status, 0);
    w.pid = -1;
    w.to = w.from = -1;
    if (WIFSIGNALED(status)) return "signal " + std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) + ")";
    return "exit code " + std::to_string(WEXITSTATUS(status));
  }
};

ProcessPoolEvaluator::ProcessPoolEvaluator(std::vector<SimConfig> tasks, int workers, double timeout_seconds,
                                           WorkerJob work)
    : impl_(std::make_unique<Impl>()) {
  ::signal(SIGPIPE, SIG_IGN);  // a dead worker shows as a failed write, not a dead parent
  impl_->tasks = std::move(tasks);
  impl_->work = work ? std::move(work) : WorkerJob(evaluate_genotype);
  impl_->timeout = timeout_seconds;
  impl_->workers.resize(std::max(workers, 1));
  for (auto& w : impl_->workers) impl_->spawn(w);
}

ProcessPoolEvaluator::~ProcessPoolEvaluator() {
  for (auto& w : impl_->workers)
    if (w.pid > 0) impl_->reap(w, false);  // closing its pipe ends the worker
}

int ProcessPoolEvaluator::workers() const { return static_cast<int>(impl_->workers.size()); }

std::vector<EvalOutcome> ProcessPoolEvaluator::evaluate(const std::vector<EvalJob>& jobs) {
  auto& im = *impl_;
  std::vector<EvalOutcome> out(jobs.size());
  // longest jobs first; results still come back in job order
  const std::vector<int> order = longest_first(jobs);
  std::deque<int> pending(order.begin(), order.end());
  std::size_t done = 0;
  // a worker lost on a job (killed from outside, stopped past the timeout, or
  // crashed by the job itself) gets the job again on a fresh worker, once: a
  // lost worker then costs nothing and the run stays as an undisturbed one,
  // while a job that crashes or hangs twice (it would every time: an
  // evaluation is a pure function of its inputs) is recorded as failed
  std::vector<int> lost(jobs.size(), 0);
  auto lose_job = [&](int job, const std::string& why) {
    if (++lost[job] < 2) {
      pending.push_front(job);
      return;
    }
    out[job].result.failed = true;
    out[job].result.failure = why + " (twice)";
    ++done;
  };

  while (done < jobs.size()) {
    // hand jobs to idle workers
    for (auto& w : im.workers) {
      if (w.job >= 0 || pending.empty()) continue;
      int j = pending.front();
      pending.pop_front();
      json msg = job_to_json(jobs[j]);
      w.job = j;
      w.deadline = std::chrono::steady_clock::now() +
                   std::chrono::milliseconds(static_cast<long>(im.timeout * 1000));
      if (!send_message(w.to, msg.dump())) {
        w.job = -1;
        lose_job(j, "worker crashed: " + im.reap(w, true));
        im.spawn(w);
      }
    }
    // wait for an answer, or for the nearest deadline
    std::vector<pollfd> fds;
    std::vector<Impl::Worker*> busy;
    auto now = std::chrono::steady_clock::now();
    auto next = now + std::chrono::hours(1);
    for (auto& w : im.workers) {
      if (w.job < 0) continue;
      fds.push_back({w.from, POLLIN, 0});
      busy.push_back(&w);
      next = std::min(next, w.deadline);
    }
    if (fds.empty()) continue;
    int wait_ms = static_cast<int>(std::max<long>(
        0, std::chrono::duration_cast<std::chrono::milliseconds>(next - now).count() + 1));
    int n = ::poll(fds.data(), fds.size(), wait_ms);
    if (n < 0 && errno != EINTR) throw std::runtime_error("poll failed");
    now = std::chrono::steady_clock::now();
    for (std::size_t k = 0; k < fds.size(); ++k) {
      Impl::Worker& w = *busy[k];
      int j = w.job;
      if (fds[k].revents & (POLLIN | POLLHUP | POLLERR)) {
        std::string msg;
        if (receive_message(w.from, msg)) {
          auto o = outcome_from_json(json::parse(msg, nullptr, false));
          if (o) {
            out[j] = std::move(o.value());
          } else {  // not expected: both ends run this program's serialiser
            out[j].result.failed = true;
            out[j].result.failure = "worker sent an unreadable result (" + o.error() + ")";
          }
          w.job = -1;
          ++done;
        } else {
          w.job = -1;
          lose_job(j, "worker crashed: " + im.reap(w, true));
          im.spawn(w);
        }
      } else if (now >= w.deadline) {
        w.job = -1;
        im.reap(w, true);
        lose_job(j, "timed out after " + std::to_string(static_cast<int>(im.timeout)) + " s");
        im.spawn(w);
      }
    }
  }
  return out;
}

std::unique_ptr<Evaluator> make_evaluator(const std::vector<SimConfig>& tasks, int workers, double timeout_seconds) {
  if (workers <= 0) return std::make_unique<SerialEvaluator>(tasks);
  return std::make_unique<ProcessPoolEvaluator>(tasks, workers, timeout_seconds);
}

}  // namespace bx
