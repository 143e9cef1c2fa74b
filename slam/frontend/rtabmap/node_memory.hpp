#pragma once
// RTAB-Map's memory of nodes (Labbé & Michaud 2013, section III-A; Memory.cpp):
//   STM  the newest Mem/STMSize nodes. Never searched for loop closures (they look like the
//        current node anyway); the oldest leaves for WM when a new node arrives.
//   WM   the nodes loop closures are searched among.
//   LTM  nodes out of reach: neither scored nor verified until retrieved.
// Every node is in exactly one of the three. Weights count rehearsal: a node that merged with
// its successor (they looked alike, the robot barely moved) carries the successor's weight + 1.
// Transfers take the lowest weight first, the oldest among equals (Memory::getRemovableSignatures
// sorts by weight, age, id).

#include <deque>
#include <functional>
#include <set>
#include <vector>

#include "slam/frontend/rtabmap/visual_vocabulary.hpp"

namespace wifislam::slam::frontend::rtabmap {

enum class MemoryPlace { kStm, kWm, kLtm, kUnknown };
const char* to_string(MemoryPlace place);

class NodeMemory {
 public:
  explicit NodeMemory(int stm_size);

  /// A new node enters STM (ids must grow). Returns the node that left STM for WM, or -1.
  NodeId add(NodeId node);
  MemoryPlace place(NodeId node) const;

  const std::deque<NodeId>& stm() const { return stm_; }
  const std::set<NodeId>& wm() const { return wm_; }
  const std::set<NodeId>& ltm() const { return ltm_; }
  std::size_t in_memory() const { return stm_.size() + wm_.size(); }

  int weight(NodeId node) const { return weights_.at(static_cast<std::size_t>(node)); }
  /// Rehearsal (Memory::rehearsalMerge with Mem/RehearsalIdUpdatedToNewOne false): `older`
  /// survives with weight(older) + weight(newer) + 1; `newer` keeps weight 0.
  void merge(NodeId older, NodeId newer);

  /// Moves up to `count` WM nodes to LTM, lowest weight first, then oldest, skipping every node
  /// `kept` says to keep. Returns the nodes moved, in that order.
  std::vector<NodeId> transfer(std::size_t count, const std::function<bool(NodeId)>& kept);
  /// Moves an LTM node back to WM (throws std::logic_error for a node not in LTM).
  void retrieve(NodeId node);

 private:
  std::size_t stm_size_;
  std::deque<NodeId> stm_;
  std::set<NodeId> wm_, ltm_;
  std::vector<int> weights_;
};

}  // namespace wifislam::slam::frontend::rtabmap
