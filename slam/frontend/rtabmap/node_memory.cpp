#include "slam/frontend/rtabmap/node_memory.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace wifislam::slam::frontend::rtabmap {

const char* to_string(MemoryPlace place) {
  switch (place) {
    case MemoryPlace::kStm:
      return "stm";
    case MemoryPlace::kWm:
      return "wm";
    case MemoryPlace::kLtm:
      return "ltm";
    case MemoryPlace::kUnknown:
      break;
  }
  return "unknown";
}

NodeMemory::NodeMemory(int stm_size) : stm_size_(static_cast<std::size_t>(std::max(0, stm_size))) {}

NodeId NodeMemory::add(NodeId node) {
  if (node < 0 || static_cast<std::size_t>(node) != weights_.size()) {
    throw std::logic_error("NodeMemory: node " + std::to_string(node) + " added, expected " +
                           std::to_string(weights_.size()));
  }
  weights_.push_back(0);
  stm_.push_back(node);
  if (stm_.size() <= stm_size_) return -1;
  const NodeId leaving = stm_.front();
  stm_.pop_front();
  wm_.insert(leaving);
  return leaving;
}

MemoryPlace NodeMemory::place(NodeId node) const {
  if (node < 0 || static_cast<std::size_t>(node) >= weights_.size()) return MemoryPlace::kUnknown;
  if (wm_.contains(node)) return MemoryPlace::kWm;
  if (ltm_.contains(node)) return MemoryPlace::kLtm;
  return MemoryPlace::kStm;
}

void NodeMemory::merge(NodeId older, NodeId newer) {
  auto& w_old = weights_.at(static_cast<std::size_t>(older));
  auto& w_new = weights_.at(static_cast<std::size_t>(newer));
  w_old += w_new + 1;
  w_new = 0;
}

std::vector<NodeId> NodeMemory::transfer(std::size_t count,
                                         const std::function<bool(NodeId)>& kept) {
  std::vector<NodeId> order;
  for (NodeId id : wm_) {
    if (!kept(id)) order.push_back(id);
  }
  // wm_ is ascending, so a stable sort by weight leaves the oldest first among equal weights.
  std::stable_sort(order.begin(), order.end(),
                   [&](NodeId a, NodeId b) { return weight(a) < weight(b); });
  if (order.size() > count) order.resize(count);
  for (NodeId id : order) {
    wm_.erase(id);
    ltm_.insert(id);
  }
  return order;
}

void NodeMemory::retrieve(NodeId node) {
  if (!ltm_.erase(node)) {
    throw std::logic_error("NodeMemory: node " + std::to_string(node) + " retrieved, not in LTM");
  }
  wm_.insert(node);
}

}  // namespace wifislam::slam::frontend::rtabmap
