#include "cli/child_process.h"

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <sstream>

extern char** environ;

namespace bx {

namespace fs = std::filesystem;

std::optional<std::string> find_program(const std::string& name) {
  auto ok = [](const fs::path& p) { return ::access(p.c_str(), X_OK) == 0 && !fs::is_directory(p); };
  if (name.find('/') != std::string::npos) return ok(name) ? std::optional(name) : std::nullopt;
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "/usr/bin:/bin");
  for (std::string d; std::getline(dirs, d, ':');)
    if (!d.empty() && ok(fs::path(d) / name)) return (fs::path(d) / name).string();
  return std::nullopt;
}

Result<std::string> find_chromium(const std::string& who, const std::string& install) {
  const char* env = std::getenv("BESTIARY_CHROMIUM");
  if (env && *env) {
    if (auto chromium = find_program(env)) return *chromium;
    return Error{std::string("BESTIARY_CHROMIUM: no such program: ") + env};
  }
  auto chromium = find_program("/usr/bin/chromium");
  if (!chromium) chromium = find_program("chromium");
  if (!chromium) return Error{who + ": chromium not found (" + install + ")"};
  return *chromium;
}

Ended run_program(const std::vector<std::string>& argv, const std::function<void(const std::string&)>& on_line) {
  std::vector<char*> args;
  for (const auto& s : argv) args.push_back(const_cast<char*>(s.c_str()));
  args.push_back(nullptr);
  int out[2], err[2];
  if (::pipe2(out, O_CLOEXEC) != 0) return {};
  if (::pipe2(err, O_CLOEXEC) != 0) {
    ::close(out[0]);
    ::close(out[1]);
    return {};
  }
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&fa, out[1], 1);
  posix_spawn_file_actions_adddup2(&fa, err[1], 2);
  pid_t pid;
  int rc = posix_spawn(&pid, args[0], &fa, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  ::close(out[1]);
  ::close(err[1]);
  Ended end;
  if (rc != 0) {
    ::close(out[0]);
    ::close(err[0]);
    return end;
  }

  // whole lines: stdout's to on_line, stderr's non-empty ones kept as the last
  std::string pending[2];
  auto take = [&](int i, const std::string& line) {
    if (i == 0) on_line(line);
    else if (line.find_first_not_of(" \t\r") != std::string::npos) end.last_err = line;
  };
  pollfd fds[2] = {{out[0], POLLIN, 0}, {err[0], POLLIN, 0}};
  bool exited = false;
  int status = 0;
  while (fds[0].fd >= 0 || fds[1].fd >= 0) {
    int n = ::poll(fds, 2, exited ? 0 : 500);
    if (n < 0 && errno != EINTR) break;
    if (n == 0 && exited) break;  // drained
    for (int i = 0; i < 2 && n > 0; ++i) {
      if (fds[i].fd < 0 || !fds[i].revents) continue;
      char buf[4096];
      ssize_t got = ::read(fds[i].fd, buf, sizeof buf);
      if (got < 0 && errno == EINTR) continue;
      if (got <= 0) {
        ::close(fds[i].fd);
        fds[i].fd = -1;
        continue;
      }
      pending[i].append(buf, static_cast<std::size_t>(got));
      for (std::size_t nl; (nl = pending[i].find('\n')) != std::string::npos; pending[i].erase(0, nl + 1))
        take(i, pending[i].substr(0, nl));
    }
    if (!exited && ::waitpid(pid, &status, WNOHANG) == pid) exited = true;
  }
  for (int i = 0; i < 2; ++i) {
    if (fds[i].fd >= 0) ::close(fds[i].fd);
    if (!pending[i].empty()) take(i, pending[i]);
  }
  if (!exited)
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
  end.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return end;
}

}  // namespace bx
