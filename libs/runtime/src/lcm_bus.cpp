#include "vsl/runtime/lcm_bus.hpp"

#include <lcm/lcm-cpp.hpp>

#include <unistd.h>

#include <cstdio>
#include <exception>
#include <list>
#include <stdexcept>
#include <string_view>
#include <utility>

namespace vsl::runtime {

namespace {

// LCM subscribes to a (glib) regular expression; the Bus promises exact channel names.
std::string escape_regex(const std::string& channel) {
  std::string out;
  for (const char c : channel) {
    if (std::string_view(".[]{}()\\*+?^$|").find(c) != std::string_view::npos) out.push_back('\\');
    out.push_back(c);
  }
  return out;
}

// liblcm explains why it cannot open a URL on stderr, itself. While it opens one, its stderr goes
// to a temporary file instead, so that the daemon's own error can carry the reason in one line.
class CapturedStderr {
 public:
  CapturedStderr() : file_(std::tmpfile()) {
    std::fflush(stderr);
    if (file_ != nullptr) saved_ = ::dup(STDERR_FILENO);
    if (saved_ >= 0) ::dup2(::fileno(file_), STDERR_FILENO);
  }
  ~CapturedStderr() { restore(); }
  CapturedStderr(const CapturedStderr&) = delete;
  CapturedStderr& operator=(const CapturedStderr&) = delete;

  // Puts stderr back and returns what was written to it, on one line.
  std::string release() {
    restore();
    std::string text;
    if (file_ == nullptr) return text;
    std::rewind(file_);
    char buffer[512];
    while (text.size() < 2000 && std::fgets(buffer, sizeof buffer, file_) != nullptr) {
      text += buffer;
    }
    for (char& c : text) {
      if (c == '\n' || c == '\r') c = ' ';
    }
    while (!text.empty() && text.back() == ' ') text.pop_back();
    return text;
  }

 private:
  void restore() {
    if (saved_ >= 0) {
      std::fflush(stderr);
      ::dup2(saved_, STDERR_FILENO);
      ::close(saved_);
      saved_ = -1;
    }
  }
  std::FILE* file_;
  int saved_ = -1;
};

}  // namespace

struct LcmBus::Impl {
  struct Subscription {
    Impl* impl = nullptr;
    RawHandler handler;
  };

  explicit Impl(std::string url_in) : url(std::move(url_in)), lcm(url) {}

  // liblcm is C: an exception must not unwind through it. Keep the first one for handle().
  static void dispatch(const lcm::ReceiveBuffer* buffer, const std::string& /*channel*/,
                       Subscription* subscription) {
    Impl& impl = *subscription->impl;
    if (impl.pending_exception) return;
    try {
      subscription->handler(
          Bytes(static_cast<const std::uint8_t*>(buffer->data), buffer->data_size),
          buffer->recv_utime);
    } catch (...) {
      impl.pending_exception = std::current_exception();
    }
  }

  std::string url;
  bool replay = url.rfind("file://", 0) == 0;
  lcm::LCM lcm;
  std::list<Subscription> subscriptions;  // stable addresses: liblcm keeps pointers to them
  std::exception_ptr pending_exception;
  bool publish_failure_logged = false;
};

LcmBus::LcmBus(std::string url, Logger log) : Bus(std::move(log)) {
  CapturedStderr captured;
  impl_ = std::make_unique<Impl>(std::move(url));
  const std::string said = captured.release();
  if (!impl_->lcm.good()) {
    throw std::runtime_error("cannot open LCM URL '" + impl_->url + "'" +
                             (said.empty() ? "" : ": liblcm says: " + said));
  }
}

LcmBus::~LcmBus() = default;

bool LcmBus::publish(const std::string& channel, Bytes bytes) {
  if (impl_->lcm.publish(channel, bytes.data(), static_cast<unsigned int>(bytes.size())) != 0) {
    ++counters().publish_errors;
    if (!impl_->publish_failure_logged) {  // once: a read-only replay would repeat it forever
      impl_->publish_failure_logged = true;
      log().warn(channel, ": cannot publish ", bytes.size(), " bytes on ", impl_->url,
                 " (further failures are only counted)");
    }
    return false;
  }
  ++counters().messages_published;
  return true;
}

void LcmBus::do_subscribe(const std::string& channel, RawHandler handler, int queue_capacity) {
  Impl::Subscription& subscription =
      impl_->subscriptions.emplace_back(Impl::Subscription{impl_.get(), std::move(handler)});
  lcm::Subscription* lcm_subscription =
      impl_->lcm.subscribeFunction(escape_regex(channel), &Impl::dispatch, &subscription);
  if (lcm_subscription == nullptr) {
    impl_->subscriptions.pop_back();
    throw std::runtime_error("cannot subscribe to '" + channel + "' on " + impl_->url);
  }
  lcm_subscription->setQueueCapacity(queue_capacity);
}

HandleResult LcmBus::handle(std::chrono::milliseconds timeout) {
  const int status = timeout.count() < 0
                         ? impl_->lcm.handle()
                         : impl_->lcm.handleTimeout(static_cast<int>(timeout.count()));
  if (impl_->pending_exception) {
    ++counters().messages_received;
    std::rethrow_exception(std::exchange(impl_->pending_exception, nullptr));
  }
  if (status > 0 || (status == 0 && timeout.count() < 0)) {
    ++counters().messages_received;
    return HandleResult::kMessage;
  }
  if (status == 0) return HandleResult::kTimeout;
  // liblcm 1.3.1's log provider answers -1 (with a readable descriptor) once the log is exhausted.
  return impl_->replay ? HandleResult::kEndOfLog : HandleResult::kError;
}

int LcmBus::fileno() {
  return impl_->lcm.getFileno();
}

const std::string& LcmBus::url() const {
  return impl_->url;
}

}  // namespace vsl::runtime
