#include "vsl/runtime/in_process_bus.hpp"

#include <algorithm>
#include <deque>
#include <map>

namespace vsl::runtime {

class InProcessHub::Endpoint final : public Bus {
 public:
  Endpoint(InProcessHub& hub, Logger log, const std::string& name)
      : Bus(std::move(log)), hub_(&hub), url_("inprocess://" + name) {
    hub_->endpoints_.push_back(this);
  }
  ~Endpoint() override {
    if (hub_ != nullptr) std::erase(hub_->endpoints_, this);
  }

  bool publish(const std::string& channel, Bytes bytes) override {
    if (hub_ == nullptr) {
      ++counters().publish_errors;
      return false;
    }
    ++counters().messages_published;
    hub_->deliver(channel, bytes);
    return true;
  }
  HandleResult handle(std::chrono::milliseconds) override {
    if (queue_.empty()) return HandleResult::kTimeout;
    Message message = std::move(queue_.front());
    queue_.pop_front();
    ++counters().messages_received;
    const auto found = handlers_.find(message.channel);
    if (found != handlers_.end()) {
      // A handler may subscribe: iterate over a copy of the list as it was.
      const std::vector<RawHandler> handlers = found->second;
      for (const RawHandler& handler : handlers) handler(message.bytes, message.receive_utime);
    }
    return HandleResult::kMessage;
  }
  int fileno() override { return -1; }
  const std::string& url() const override { return url_; }

  void receive(const std::string& channel, Bytes bytes, std::int64_t receive_utime) {
    if (!handlers_.contains(channel)) return;  // as LCM: only subscribed channels arrive
    queue_.push_back(
        {channel, std::vector<std::uint8_t>(bytes.begin(), bytes.end()), receive_utime});
  }
  std::size_t queued() const { return queue_.size(); }
  void detach() { hub_ = nullptr; }

 protected:
  void do_subscribe(const std::string& channel, RawHandler handler, int) override {
    handlers_[channel].push_back(std::move(handler));
  }

 private:
  struct Message {
    std::string channel;
    std::vector<std::uint8_t> bytes;
    std::int64_t receive_utime = 0;
  };

  InProcessHub* hub_;
  std::string url_;
  std::map<std::string, std::vector<RawHandler>> handlers_;
  std::deque<Message> queue_;
};

InProcessHub::~InProcessHub() {
  for (Endpoint* endpoint : endpoints_) endpoint->detach();
}

std::unique_ptr<Bus> InProcessHub::connect(Logger log, const std::string& name) {
  return std::make_unique<Endpoint>(*this, std::move(log), name);
}

std::size_t InProcessHub::pending() const {
  std::size_t n = 0;
  for (const Endpoint* endpoint : endpoints_) n += endpoint->queued();
  return n;
}

void InProcessHub::deliver(const std::string& channel, Bytes bytes) {
  const std::int64_t now = clock_.utime();
  for (Endpoint* endpoint : endpoints_) endpoint->receive(channel, bytes, now);
}

}  // namespace vsl::runtime
