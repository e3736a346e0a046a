// `bestiary show RUN --watch`: the run's page served on 127.0.0.1 follows the
// run while it goes on. In headless Chromium (viewer/tools/watch_check.mjs): a
// page opened at generation 2, with a creature and a moment chosen, reloads
// once the run (resumed beside it) has stored its other generations, and
// keeps that creature and moment; the page file is kept current too. And
// what it refuses, in one line.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fcntl.h>
#include <regex>
#include <string>
#include <thread>

#include "support/run_command.h"

namespace {

using namespace bxtest;
using nlohmann::json;

class ShowWatch : public InTempDir {};

TEST_F(ShowWatch, APageFollowsTheRunInChromiumAndKeepsWhatWasWatched) {
  const fs::path cfg = write("w.toml", "[genome]\ndialect = \"sims1994\"\n[evolution]\npopulation = 12\n"
                                       "generations = 8\n[task]\nseconds = 2\n");
  const fs::path run = dir / "run", log = dir / "watch.log";
  ASSERT_EQ(bestiary("run " + cfg.string() + " --out " + run.string() + " --stop-after 2 --quiet --workers 1").code, 0);
  // the watcher, on any free port, its output to a file
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(fd, 1);
    ::dup2(fd, 2);
    ::execl(BESTIARY_BINARY, BESTIARY_BINARY, "show", run.c_str(), "--watch", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  const std::regex served(R"(watching at http://127\.0\.0\.1:([0-9]+)/)");
  std::smatch m;
  std::string said;
  for (auto until = std::chrono::steady_clock::now() + std::chrono::seconds(60);
       std::chrono::steady_clock::now() < until && !std::regex_search(said, m, served);) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    said = slurp(log);
  }
  ASSERT_TRUE(std::regex_search(said, m, served)) << said;
  const std::string url = "http://127.0.0.1:" + m[1].str() + "/";
  EXPECT_NE(said.find("2 generations"), std::string::npos) << said;
  Outcome r = run_command("node " + std::string(BESTIARY_SOURCE_DIR) + "/viewer/tools/watch_check.mjs --url " + url +
                          " --then '" + BESTIARY_BINARY + " resume " + run.string() + " --quiet --workers 1'");
  ::kill(pid, SIGTERM);
  ::waitpid(pid, nullptr, 0);
  ASSERT_EQ(r.code, 0) << r.err;
  const json seen = json::parse(r.out);
  EXPECT_EQ(seen["before"]["generations"], 2) << seen;
  EXPECT_EQ(seen["after"]["generations"], 8) << seen;
  EXPECT_GE(seen["reloads"].get<int>(), 1) << seen;
  EXPECT_TRUE(seen["errors"].empty()) << seen;
  // what was watched: the same creature, at the same moment, still paused
  EXPECT_EQ(seen["after"]["label"], seen["before"]["label"]) << seen;
  EXPECT_EQ(seen["after"]["t"], 1.5) << seen;
  EXPECT_EQ(seen["after"]["playing"], false) << seen;
  // the page file, kept current, and what the watcher said as it went
  const json data = json::parse(embedded_data(slurp(run / "view.html")));
  EXPECT_EQ(data["run"]["generations"].size(), 8u);
  EXPECT_EQ(data["run"]["watch"]["stamp"].get<std::string>().rfind("8 generations, ", 0), 0u) << data["run"]["watch"];
  EXPECT_NE(slurp(log).find("run: 8 generations"), std::string::npos) << slurp(log);
}

TEST_F(ShowWatch, WhatItCannotFollowIsRefusedInOneLine) {
  const fs::path run = dir / "run";
  ASSERT_EQ(small_run(run).code, 0);
  for (const std::string& bad : {creature("walker.json") + " --watch", run.string() + " " + run.string() + " --watch --out x.html",
                                 run.string() + ":1 --watch", run.string() + " --port 8000"}) {
    Outcome o = bestiary("show " + bad);
    EXPECT_EQ(o.code, 2) << bad;
    EXPECT_EQ(std::count(o.err.begin(), o.err.end(), '\n'), 1) << o.err;
    EXPECT_NE(o.err.find("--watch"), std::string::npos) << o.err;
  }
}

}  // namespace
