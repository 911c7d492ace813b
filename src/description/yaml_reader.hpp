// YAML for the description and rule readers: a document loaded with libyaml into located
// nodes, and small helpers for schema-checked reading.
#pragma once

#include <cstddef>
#include <deque>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/diagnostics.hpp"
#include "description/description.hpp"

namespace tackle::yaml {

enum class NodeType { Undefined, Null, Scalar, Sequence, Map };

/// A position in the text, 0-based as libyaml gives it; -1 where there is none (an empty file).
struct Mark {
  int line = -1;
  int column = -1;
};

/// One node of a loaded document, as libyaml's events make it.
struct NodeData {
  NodeType type = NodeType::Null;
  Mark mark;
  bool quoted = false;                 // a quoted or block scalar with no explicit tag
  std::string scalar;                  // a scalar's text
  std::vector<const NodeData*> items;  // a list's items; a mapping's keys and values, alternating
};

struct Entry;

/// A read-only view of a node of a Document (which must outlive it). A default-made Node, or
/// the value of a key a mapping does not have, is undefined: `if (map["key"])` asks whether
/// the key is there.
class Node {
 public:
  Node() = default;
  explicit Node(const NodeData* d) : d_(d) {}

  NodeType type() const { return d_ ? d_->type : NodeType::Undefined; }
  bool defined() const { return d_ != nullptr; }
  bool is_null() const { return type() == NodeType::Null; }
  bool is_scalar() const { return type() == NodeType::Scalar; }
  bool is_sequence() const { return type() == NodeType::Sequence; }
  bool is_map() const { return type() == NodeType::Map; }
  explicit operator bool() const { return defined(); }

  /// A scalar's text ("" for anything else).
  const std::string& text() const;
  /// A quoted or block scalar (its mark is the quote or the indicator).
  bool quoted() const { return d_ && d_->quoted; }
  Mark mark() const { return d_ ? d_->mark : Mark{}; }
  /// Items of a list, entries of a mapping, 0 otherwise.
  std::size_t size() const;

  /// The value of the first entry whose key is the scalar `key`; undefined when there is none
  /// or this is not a mapping.
  Node operator[](std::string_view key) const;
  /// The i-th item of a list; undefined past the end or when this is not a list.
  Node operator[](std::size_t i) const;
  Node operator[](int i) const { return (*this)[static_cast<std::size_t>(i)]; }

  class iterator;
  iterator begin() const;
  iterator end() const;

 private:
  const NodeData* d_ = nullptr;
};

/// An entry met when walking a node: the item itself for a list; for a mapping, the key as
/// `first` and the value as `second` (and the entry itself is the value).
struct Entry : Node {
  Node first;
  Node second;
};

class Node::iterator {
 public:
  iterator(const NodeData* d, std::size_t i) : d_(d), i_(i) {}
  Entry operator*() const;
  iterator& operator++() {
    i_ += d_ && d_->type == NodeType::Map ? 2 : 1;
    return *this;
  }
  bool operator==(const iterator& o) const { return i_ == o.i_; }
  bool operator!=(const iterator& o) const { return i_ != o.i_; }

 private:
  const NodeData* d_;
  std::size_t i_;
};

/// A loaded YAML document: owns every node. Not copyable; its nodes stay where they are when
/// it is moved.
class Document {
 public:
  Document() = default;
  Document(Document&&) = default;
  Document& operator=(Document&&) = default;
  Document(const Document&) = delete;
  Document& operator=(const Document&) = delete;

  Node root() const { return Node(root_); }

 private:
  friend class Loader;
  std::unique_ptr<std::deque<NodeData>> nodes_ = std::make_unique<std::deque<NodeData>>();
  const NodeData* root_ = nullptr;
};

/// Location of a node (1-based; a quoted scalar's column is its first character's).
Location where(const Node& n, const std::string& file);

/// Loads the first YAML document of the text with libyaml. A syntax error is reported as a
/// located diagnostic, and the document's root is then undefined; an empty text's root is
/// null.
Document load(const std::string& text, const std::string& file, Diagnostics& diags);

/// True for a sequence; otherwise reports "WHAT is a mapping (expected a list)".
bool is_list(const Node& n, const std::string& what, const std::string& file, Diagnostics& diags);

/// Checks the keys of a map: unknown keys (with the nearest allowed key suggested) and
/// duplicate keys are reported. Returns false when the node is not a map.
bool check_map(const Node& map, const std::vector<std::string>& allowed, const std::string& what,
               const std::string& file, Diagnostics& diags);

/// Reports keys that occur twice in a map (both are kept).
void check_unique_keys(const Node& map, const std::string& what, const std::string& file, Diagnostics& diags);

/// A scalar as located text; reports and returns nullopt when the node is not a scalar.
std::optional<Text> scalar(const Node& n, const std::string& what, const std::string& file, Diagnostics& diags);

/// A scalar or a list of scalars.
std::optional<std::vector<Text>> scalar_list(const Node& n, const std::string& what, const std::string& file,
                                             Diagnostics& diags);

/// "a mapping", "a list", "a scalar" for messages.
std::string kind_name(const Node& n);

}  // namespace tackle::yaml
