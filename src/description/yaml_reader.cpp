#include "description/yaml_reader.hpp"

#include <algorithm>
#include <new>
#include <optional>
#include <set>
#include <string_view>
#include <unordered_map>

#include <yaml.h>

#include <fmt/format.h>

#include "core/utf8.hpp"

namespace tackle::yaml {

namespace {
const std::string empty_text;

// Line and column (0-based) of a byte offset.
Mark mark_at(const std::string& text, std::size_t offset) {
  offset = std::min(offset, text.size());
  const auto begin = text.begin();
  const int line = static_cast<int>(std::count(begin, begin + static_cast<std::ptrdiff_t>(offset), '\n'));
  const auto line_start = offset == 0 ? std::string::npos : text.rfind('\n', offset - 1);
  const std::size_t column = line_start == std::string::npos ? offset : offset - line_start - 1;
  return {line, static_cast<int>(column)};
}

bool null_text(std::string_view s) { return s.empty() || s == "~" || s == "null" || s == "Null" || s == "NULL"; }
}  // namespace

const std::string& Node::text() const { return d_ && d_->type == NodeType::Scalar ? d_->scalar : empty_text; }

std::size_t Node::size() const {
  if (!d_) return 0;
  if (d_->type == NodeType::Sequence) return d_->items.size();
  if (d_->type == NodeType::Map) return d_->items.size() / 2;
  return 0;
}

Node Node::operator[](std::string_view key) const {
  if (!d_ || d_->type != NodeType::Map) return {};
  for (std::size_t i = 0; i + 1 < d_->items.size(); i += 2)
    if (d_->items[i]->type == NodeType::Scalar && d_->items[i]->scalar == key) return Node(d_->items[i + 1]);
  return {};
}

Node Node::operator[](std::size_t i) const {
  if (!d_ || d_->type != NodeType::Sequence || i >= d_->items.size()) return {};
  return Node(d_->items[i]);
}

Node::iterator Node::begin() const { return {d_, 0}; }
Node::iterator Node::end() const {
  return {d_, d_ && (d_->type == NodeType::Sequence || d_->type == NodeType::Map) ? d_->items.size() : 0};
}

Entry Node::iterator::operator*() const {
  Entry e;
  if (d_->type == NodeType::Map) {
    e.first = Node(d_->items[i_]);
    e.second = Node(d_->items[i_ + 1]);
    static_cast<Node&>(e) = e.second;
  } else {
    static_cast<Node&>(e) = Node(d_->items[i_]);
  }
  return e;
}

Location where(const Node& n, const std::string& file) {
  const Mark m = n.mark();
  if (m.line < 0) return {file, 0, 0};
  // A quoted scalar's mark is its opening quote; columns inside it count from the first
  // character after the quote.
  return {file, m.line + 1, m.column + 1 + (n.is_scalar() && n.quoted() ? 1 : 0)};
}

// Builds a Document from libyaml's events of the first document (later ones are not read).
class Loader {
 public:
  Loader(const std::string& text, const std::string& file, Diagnostics& diags)
      : text_(text), file_(file), diags_(diags) {
    yaml_parser_initialize(&parser_);
    yaml_parser_set_input_string(&parser_, reinterpret_cast<const unsigned char*>(text.data()), text.size());
    yaml_parser_set_encoding(&parser_, YAML_UTF8_ENCODING);
  }
  ~Loader() { yaml_parser_delete(&parser_); }
  Loader(const Loader&) = delete;
  Loader& operator=(const Loader&) = delete;

  Document run() {
    Document doc;
    for (;;) {
      yaml_event_t ev;
      if (!yaml_parser_parse(&parser_, &ev)) {
        report_parser_error();
        doc.root_ = nullptr;
        return doc;
      }
      // No event without an error: libyaml ran out of memory on the way (it then answers
      // every call with an empty event, and this loop would never end).
      if (ev.type == YAML_NO_EVENT) {
        yaml_event_delete(&ev);
        throw std::bad_alloc();
      }
      const bool done = handle(ev, doc);
      yaml_event_delete(&ev);
      if (failed_) {
        doc.root_ = nullptr;
        return doc;
      }
      if (done) break;
    }
    if (!doc.root_) {  // no document at all: an empty (or comment-only) text
      doc.nodes_->emplace_back();
      doc.root_ = &doc.nodes_->back();
    }
    return doc;
  }

 private:
  static std::string_view text_of(const yaml_char_t* s) {
    return s ? std::string_view(reinterpret_cast<const char*>(s)) : std::string_view();
  }

  static Mark mark_of(const yaml_mark_t& m) { return {static_cast<int>(m.line), static_cast<int>(m.column)}; }

  Location location(const yaml_mark_t& m) const {
    return {file_, static_cast<int>(m.line) + 1, static_cast<int>(m.column) + 1};
  }

  NodeData* make(Document& doc, NodeType type, const yaml_mark_t& m) {
    NodeData& d = doc.nodes_->emplace_back();
    d.type = type;
    d.mark = mark_of(m);
    return &d;
  }

  // Puts a complete node into the collection being read (or makes it the root), counting the
  // nodes a reader walks in it.
  void attach(Document& doc, const NodeData* d, std::size_t walked) {
    if (open_.empty()) {
      doc.root_ = d;
      return;
    }
    open_.back().node->items.push_back(d);
    open_.back().walked += walked;
  }

  // True when the first document has ended.
  bool handle(const yaml_event_t& ev, Document& doc) {
    switch (ev.type) {
      case YAML_DOCUMENT_END_EVENT:
      case YAML_STREAM_END_EVENT: return true;
      case YAML_SCALAR_EVENT: {
        const auto& s = ev.data.scalar;
        const std::string_view tag = text_of(s.tag);
        const bool plain = s.style == YAML_PLAIN_SCALAR_STYLE || s.style == YAML_ANY_SCALAR_STYLE;
        const std::string_view value(reinterpret_cast<const char*>(s.value), s.length);
        NodeData* d = make(doc, plain && !s.tag && null_text(value) ? NodeType::Null : NodeType::Scalar, ev.start_mark);
        if (d->type == NodeType::Scalar) d->scalar.assign(value);
        d->quoted = !plain && (tag.empty() || tag == "!");
        attach(doc, d, 1);
        if (s.anchor) anchors_[std::string(text_of(s.anchor))] = {d, 1};
        return false;
      }
      case YAML_ALIAS_EVENT: {
        const std::string name(text_of(ev.data.alias.anchor));
        const auto it = anchors_.find(name);
        if (it == anchors_.end()) {
          diags_.error(location(ev.start_mark), "invalid YAML: the alias *" + name +
                                                    " names no anchor before it (expected &" + name +
                                                    " on a complete node earlier in the file)");
          failed_ = true;
          return true;
        }
        // Aliases share their node, so a reader walks it once per alias: a few aliases of
        // aliases would have it walk (and report on) billions of nodes from a small file.
        const auto& [node, walked] = it->second;
        repeated_ += walked;
        if (const std::size_t limit = std::max(repeat_limit, doc.nodes_->size()); repeated_ > limit) {
          diags_.error(location(ev.start_mark),
                       fmt::format("invalid YAML: with the alias *{}, aliases repeat {} nodes (expected at most {}, or "
                                   "as many as the file itself has)",
                                   name, repeated_, limit));
          failed_ = true;
          return true;
        }
        attach(doc, node, walked);
        return false;
      }
      case YAML_SEQUENCE_START_EVENT:
      case YAML_MAPPING_START_EVENT: {
        const bool map = ev.type == YAML_MAPPING_START_EVENT;
        const yaml_char_t* anchor = map ? ev.data.mapping_start.anchor : ev.data.sequence_start.anchor;
        open_.push_back({make(doc, map ? NodeType::Map : NodeType::Sequence, ev.start_mark),
                         anchor ? std::optional<std::string>(text_of(anchor)) : std::nullopt, 1});
        return false;
      }
      case YAML_SEQUENCE_END_EVENT:
      case YAML_MAPPING_END_EVENT: {
        const Open done = std::move(open_.back());
        open_.pop_back();
        if (done.anchor) anchors_[*done.anchor] = {done.node, done.walked};  // complete: an alias may name it now
        attach(doc, done.node, done.walked);
        return false;
      }
      default: return false;
    }
  }

  void report_parser_error() {
    failed_ = true;
    if (parser_.error == YAML_MEMORY_ERROR) {
      diags_.error({file_, 0, 0}, "invalid YAML: the document is too large to read (expected a smaller file)");
      return;
    }
    const std::string problem = parser_.problem ? parser_.problem : "unreadable text";
    Mark at;
    if (parser_.error == YAML_READER_ERROR)
      at = mark_at(text_, parser_.problem_offset);
    else
      at = mark_of(parser_.problem_mark);
    std::string msg = "invalid YAML: " + problem;
    if (parser_.context)
      msg += fmt::format(" ({} started at line {}, column {})", parser_.context, parser_.context_mark.line + 1,
                         parser_.context_mark.column + 1);
    diags_.error({file_, at.line + 1, at.column + 1}, msg);
  }

  const std::string& text_;
  const std::string& file_;
  Diagnostics& diags_;
  yaml_parser_t parser_{};
  // A collection being read: its anchor, and the nodes a reader walks in it so far (aliases
  // counted out).
  struct Open {
    NodeData* node;
    std::optional<std::string> anchor;
    std::size_t walked;
  };
  std::vector<Open> open_;
  // Each anchor's node and the nodes a reader walks in it.
  std::unordered_map<std::string, std::pair<const NodeData*, std::size_t>> anchors_;
  std::size_t repeated_ = 0;  // nodes that aliases repeat
  static constexpr std::size_t repeat_limit = 10000;
  bool failed_ = false;
};

Document load(const std::string& text, const std::string& file, Diagnostics& diags) {
  if (const auto bad = invalid_utf8_at(text)) {
    const Mark m = mark_at(text, *bad);
    diags.error({file, m.line + 1, m.column + 1}, fmt::format("invalid UTF-8 byte 0x{:02X} (expected UTF-8 text)",
                                                              static_cast<unsigned char>(text[*bad])));
    return Document();
  }
  return Loader(text, file, diags).run();
}

std::string kind_name(const Node& n) {
  switch (n.type()) {
    case NodeType::Map: return "a mapping";
    case NodeType::Sequence: return "a list";
    case NodeType::Scalar: return "a scalar";
    default: return "nothing";
  }
}

bool is_list(const Node& n, const std::string& what, const std::string& file, Diagnostics& diags) {
  if (n.is_sequence()) return true;
  diags.error(where(n, file), what + " is " + kind_name(n) + " (expected a list)");
  return false;
}

bool check_map(const Node& map, const std::vector<std::string>& allowed, const std::string& what,
               const std::string& file, Diagnostics& diags) {
  if (!map.is_map()) {
    diags.error(where(map, file), what + " is " + kind_name(map) + " (expected a mapping)");
    return false;
  }
  std::set<std::string> seen;
  for (const auto& kv : map) {
    if (!kv.first.is_scalar()) {
      diags.error(where(kv.first, file), "a key in " + what + " is " + kind_name(kv.first) + " (expected a name)");
      continue;
    }
    const std::string key = kv.first.text();
    if (!seen.insert(key).second) {
      diags.error(where(kv.first, file), "duplicate key '" + key + "' in " + what);
      continue;
    }
    bool ok = false;
    for (const auto& a : allowed) ok = ok || a == key;
    if (!ok) {
      std::string msg = "unknown key '" + key + "' in " + what;
      if (auto near = nearest(key, allowed); !near.empty())
        msg += " (did you mean '" + near + "'?)";
      else
        msg += " (expected one of: " + join(allowed) + ")";
      diags.error(where(kv.first, file), msg);
    }
  }
  return true;
}

void check_unique_keys(const Node& map, const std::string& what, const std::string& file, Diagnostics& diags) {
  std::set<std::string> seen;
  for (const auto& kv : map)
    if (kv.first.is_scalar() && !seen.insert(kv.first.text()).second)
      diags.error(where(kv.first, file), "duplicate key '" + kv.first.text() + "' in " + what);
}

std::optional<Text> scalar(const Node& n, const std::string& what, const std::string& file, Diagnostics& diags) {
  if (!n.is_scalar()) {
    diags.error(where(n, file), what + " is " + kind_name(n) + " (expected a scalar)");
    return std::nullopt;
  }
  return Text{n.text(), where(n, file)};
}

std::optional<std::vector<Text>> scalar_list(const Node& n, const std::string& what, const std::string& file,
                                             Diagnostics& diags) {
  std::vector<Text> out;
  if (n.is_scalar()) {
    out.push_back({n.text(), where(n, file)});
    return out;
  }
  if (!n.is_sequence()) {
    diags.error(where(n, file), what + " is " + kind_name(n) + " (expected a list of names)");
    return std::nullopt;
  }
  bool ok = true;
  for (const auto& item : n) {
    if (auto t = scalar(item, "an item of " + what, file, diags))
      out.push_back(*t);
    else
      ok = false;
  }
  if (!ok) return std::nullopt;
  return out;
}

}  // namespace tackle::yaml
