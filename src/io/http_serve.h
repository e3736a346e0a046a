// A minimal HTTP server on the loopback interface, for `bestiary show RUN
// --watch` (a page that follows a run): GET requests answered by a handler,
// one connection at a time, and a tick between them so its owner can do
// other work (look at the run). Never reachable from another machine: it
// binds 127.0.0.1 only.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "core/result.h"

namespace bx {

/// What a GET of a path is answered with.
struct HttpReply {
  int status = 200;  ///< 200, or 404
  std::string type = "text/plain; charset=utf-8";
  std::string body;
};

class HttpServer {
 public:
  /// Listens on 127.0.0.1:`port` (0: any free port, see port()); an error
  /// names the port and why (in use, say).
  static Result<HttpServer> listen(int port);
  HttpServer(HttpServer&&) noexcept;
  HttpServer& operator=(HttpServer&&) noexcept;
  HttpServer(const HttpServer&) = delete;
  ~HttpServer();

  int port() const { return port_; }
  /// Answers requests with `handle` (the path, without its query) until
  /// `tick` returns false; `tick` runs about every `tick_seconds`, between
  /// requests. Only GET is answered (else 405).
  void serve(const std::function<HttpReply(const std::string& path)>& handle, const std::function<bool()>& tick,
             double tick_seconds);

 private:
  explicit HttpServer(int fd, int port) : fd_(fd), port_(port) {}
  int fd_ = -1;
  int port_ = 0;
};

}  // namespace bx
