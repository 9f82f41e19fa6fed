#include "scenarios/source_node.hpp"

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/parser.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <system_error>

namespace rodsort::scenarios {
namespace {

SourceLocation location_of(const YAML::Mark& mark, const std::string& source,
                           const SourceLocation& fallback) {
  if (mark.is_null()) return fallback;
  return {source, mark.line + 1, mark.column + 1};
}

// A scenario is a few hundred nodes and a few kilobytes; these bounds are a thousand times that,
// and they keep a hostile file (an alias that refers to itself, aliases nested ten deep that
// expand to billions of nodes, a file that never ends) from exhausting the stack or the memory.
constexpr std::size_t kMaxNodes = 200'000;            ///< after aliases are expanded
constexpr std::size_t kMaxExpandedText = 16'000'000;  ///< scalar bytes after expansion
constexpr std::size_t kMaxDepth = 64;                 ///< nested maps and sequences
constexpr std::uintmax_t kMaxFileBytes = 16'000'000;

/// Turns yaml-cpp's node graph into a SourceNode tree, refusing what a scenario never needs and
/// what would not end: a collection that contains itself through an alias, expansion beyond the
/// bounds above, tags. After the first refusal of a bound, conversion stops.
class Converter {
 public:
  Converter(const std::string& source, Diagnostics& diagnostics)
      : source_(source), diagnostics_(diagnostics) {}

  bool refused() const { return refused_; }

  SourceNode convert(const YAML::Node& node, const SourceLocation& fallback) {
    SourceNode out;
    out.where = location_of(node.Mark(), source_, fallback);
    if (refused_) return out;
    if (++nodes_ > kMaxNodes) {
      return refuse(out.where, "more than " + std::to_string(kMaxNodes) +
                                   " values once its aliases are expanded; a scenario needs a "
                                   "few hundred (are aliases nested inside each other?)");
    }
    if (!tag_allowed(node)) {
      diagnostics_.error(out.where, "",
                         "a YAML tag (" + node.Tag() +
                             ") is not read: write the value without it (quote a string)");
      return out;
    }
    switch (node.Type()) {
      case YAML::NodeType::Undefined:
      case YAML::NodeType::Null:
        out.kind = SourceNode::Kind::null;
        break;
      case YAML::NodeType::Scalar:
        out.kind = SourceNode::Kind::scalar;
        expanded_text_ += node.Scalar().size();
        if (expanded_text_ > kMaxExpandedText) {
          return refuse(out.where, "more than " + std::to_string(kMaxExpandedText) +
                                       " bytes of values once its aliases are expanded");
        }
        out.scalar = node.Scalar();
        // yaml-cpp tags plain scalars "?" and quoted ones "!".
        out.quoted = node.Tag() == "!";
        break;
      case YAML::NodeType::Sequence:
        out.kind = SourceNode::Kind::sequence;
        if (!open(node, out.where)) return out;
        for (const YAML::Node& item : node) {
          out.items.push_back(convert(item, out.where));
          if (refused_) break;
        }
        ancestors_.pop_back();
        break;
      case YAML::NodeType::Map: {
        out.kind = SourceNode::Kind::map;
        if (!open(node, out.where)) return out;
        std::set<std::string> seen;
        for (const auto& pair : node) {
          SourceNode::Entry entry;
          entry.key_where = location_of(pair.first.Mark(), source_, out.where);
          if (!pair.first.IsScalar()) {
            diagnostics_.error(entry.key_where, "", "a key must be a plain name, got a collection");
            continue;
          }
          entry.key = pair.first.Scalar();
          if (!seen.insert(entry.key).second) {
            diagnostics_.error(entry.key_where, entry.key,
                               "duplicate key (a key may appear once in a map)");
            continue;
          }
          entry.value = convert(pair.second, entry.key_where);
          out.entries.push_back(std::move(entry));
          if (refused_) break;
        }
        ancestors_.pop_back();
        break;
      }
    }
    return out;
  }

 private:
  // Plain scalars and collections carry the non-specific tag "?", quoted scalars "!"; anything
  // else was written by the user (`!!str 60`, `!foo 60`), and reading it as if untagged would
  // make `!!str 60` a number while `"60"` is refused.
  static bool tag_allowed(const YAML::Node& node) {
    const std::string& tag = node.Tag();
    return tag.empty() || tag == "?" || (tag == "!" && node.IsScalar());
  }

  /// Enters a collection; false (and a diagnostic) when it is one of its own ancestors or the
  /// nesting is too deep.
  bool open(const YAML::Node& node, const SourceLocation& where) {
    for (const YAML::Node& ancestor : ancestors_) {
      if (ancestor.is(node)) {
        diagnostics_.error(where, "",
                           "an alias refers to the collection that contains it, a value "
                           "without end");
        return false;
      }
    }
    if (ancestors_.size() >= kMaxDepth) {
      refuse(where, "maps and sequences nested more than " + std::to_string(kMaxDepth) +
                        " deep; a scenario needs four");
      return false;
    }
    ancestors_.push_back(node);
    return true;
  }

  SourceNode refuse(const SourceLocation& where, const std::string& why) {
    refused_ = true;
    diagnostics_.error(where, "", "the YAML holds " + why);
    SourceNode out;
    out.where = where;
    return out;
  }

  const std::string& source_;
  Diagnostics& diagnostics_;
  std::vector<YAML::Node> ancestors_;
  std::size_t nodes_ = 0;
  std::size_t expanded_text_ = 0;
  bool refused_ = false;
};

std::string quote(const std::string& text) { return "\"" + text + "\""; }

struct ControlCharacter {
  SourceLocation where;
  unsigned byte;
};

/// YAML is text: of the C0 controls only tab, line feed and carriage return may appear (YAML 1.2,
/// section 5.1). yaml-cpp loops without end, allocating, on a NUL in some places, so such a byte
/// is refused before the parser sees it.
std::optional<ControlCharacter> find_control_character(std::string_view text,
                                                       const std::string& source) {
  int line = 1;
  int column = 1;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if ((byte < 0x20 && c != '\t' && c != '\n' && c != '\r') || byte == 0x7f) {
      return ControlCharacter{{source, line, column}, byte};
    }
    if (c == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return std::nullopt;
}

/// Records where each document starts, and nothing else: counts the documents of a text.
class DocumentStarts final : public YAML::EventHandler {
 public:
  std::vector<YAML::Mark> marks;

  void OnDocumentStart(const YAML::Mark& mark) override { marks.push_back(mark); }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
  void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t,
                const std::string&) override {}
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {}
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {}
  void OnMapEnd() override {}
};

/// Whether a line of `text` starts with the document marker `---` (alone or before a space).
bool has_document_marker(std::string_view text) {
  for (std::size_t line = 0; line < text.size();) {
    const std::string_view rest = text.substr(line);
    if (rest.rfind("---", 0) == 0 && (rest.size() == 3 || rest[3] == ' ' || rest[3] == '\n' ||
                                      rest[3] == '\r' || rest[3] == '\t')) {
      return true;
    }
    const std::size_t newline = text.find('\n', line);
    if (newline == std::string_view::npos) break;
    line = newline + 1;
  }
  return false;
}

}  // namespace

const SourceNode::Entry* SourceNode::find_entry(std::string_view key) const {
  const auto it = std::find_if(entries.begin(), entries.end(),
                               [&](const Entry& entry) { return entry.key == key; });
  return it == entries.end() ? nullptr : &*it;
}

const SourceNode* SourceNode::find(std::string_view key) const {
  const Entry* entry = find_entry(key);
  return entry ? &entry->value : nullptr;
}

SourceNode* SourceNode::find(std::string_view key) {
  return const_cast<SourceNode*>(std::as_const(*this).find(key));
}

bool SourceNode::erase(std::string_view key) {
  const auto it = std::find_if(entries.begin(), entries.end(),
                               [&](const Entry& entry) { return entry.key == key; });
  if (it == entries.end()) return false;
  entries.erase(it);
  return true;
}

std::string SourceNode::describe() const {
  switch (kind) {
    case Kind::null:
      return "null";
    case Kind::scalar:
      return quoted ? quote(scalar) : scalar;
    case Kind::sequence: {
      std::string text = "[";
      for (std::size_t i = 0; i < items.size(); ++i) {
        text += (i ? ", " : "") + items[i].describe();
      }
      return text + "]";
    }
    case Kind::map: {
      std::string text = "{";
      for (std::size_t i = 0; i < entries.size(); ++i) {
        text += (i ? ", " : "") + entries[i].key + ": " + entries[i].value.describe();
      }
      return text + "}";
    }
  }
  return {};
}

std::optional<SourceNode> parse_yaml(std::string_view text, const std::string& source,
                                     Diagnostics& diagnostics) {
  if (const auto found = find_control_character(text, source)) {
    char code[8];
    std::snprintf(code, sizeof code, "0x%02x", found->byte);
    diagnostics.error(found->where, "",
                      std::string("a control character (byte ") + code +
                          ") where YAML allows only text; is this a scenario file?");
    return std::nullopt;
  }
  // The first document is loaded on its own: yaml-cpp's LoadAll can loop without end, adding
  // empty documents, on text it cannot read (its issue 1319, fixed after the 0.7 that Debian
  // ships). Then the documents are counted, stopping at the second.
  YAML::Node root;
  std::vector<YAML::Mark> document_starts;
  try {
    root = YAML::Load(std::string(text));
    std::istringstream stream{std::string(text)};
    YAML::Parser parser(stream);
    DocumentStarts starts;
    while (starts.marks.size() < 2 && parser.HandleNextDocument(starts)) {
    }
    document_starts = std::move(starts.marks);
  } catch (const YAML::DeepRecursion& e) {
    // yaml-cpp's own message for this is "bad file".
    diagnostics.error(location_of(e.mark, source, {source, 0, 0}), "",
                      "the YAML holds maps and sequences nested more than " +
                          std::to_string(e.depth()) + " deep; a scenario needs four");
    return std::nullopt;
  } catch (const YAML::Exception& e) {
    diagnostics.error(location_of(e.mark, source, {source, 0, 0}), "",
                      "YAML syntax error: " + e.msg);
    return std::nullopt;
  }
  if (document_starts.size() > 1) {
    const YAML::Mark& second = document_starts[1];
    // A second document begins with a `---` line; without one, yaml-cpp has found a "document"
    // in text it could not read.
    const bool marked =
        second.pos > document_starts[0].pos &&
        has_document_marker(text.substr(0, static_cast<std::size_t>(second.pos) + 3));
    if (!marked) {
      diagnostics.error(location_of(second, source, {source, 0, 0}), "",
                        "YAML syntax error: the text cannot be read as YAML from here");
    } else {
      diagnostics.error(location_of(second, source, {source, 0, 0}), "",
                        "a second YAML document; the text must hold one (remove the `---` and "
                        "what follows, or put it in a file of its own)");
    }
    return std::nullopt;
  }
  if (document_starts.empty()) {  // empty, or only comments
    SourceNode nothing;
    nothing.where = {source, 1, 1};
    return nothing;
  }
  Converter converter(source, diagnostics);
  SourceNode tree = converter.convert(root, {source, 1, 1});
  if (converter.refused()) return std::nullopt;
  return tree;
}

std::optional<SourceNode> read_yaml_file(const std::filesystem::path& path,
                                         Diagnostics& diagnostics) {
  const SourceLocation file{path.string(), 0, 0};
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (status.type() == std::filesystem::file_type::not_found) {
    diagnostics.error(file, "", "cannot open the file for reading: no such file");
    return std::nullopt;
  }
  if (error) {
    diagnostics.error(file, "", "cannot open the file for reading: " + error.message());
    return std::nullopt;
  }
  // Opening a FIFO would block until a writer comes, and a device may never end: refuse both
  // before opening.
  if (std::filesystem::is_directory(status)) {
    diagnostics.error(file, "", "is a directory; expected a YAML file");
    return std::nullopt;
  }
  if (!std::filesystem::is_regular_file(status)) {
    diagnostics.error(file, "",
                      "is not a regular file (a device, a pipe or a socket); expected a YAML file");
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    diagnostics.error(file, "", "cannot open the file for reading");
    return std::nullopt;
  }
  // Read at most one byte past the bound, so that a file that grows while it is read is still
  // refused rather than read without end.
  std::string text(kMaxFileBytes + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  if (text.size() > kMaxFileBytes) {
    diagnostics.error(file, "",
                      "larger than " + std::to_string(kMaxFileBytes / 1'000'000) +
                          " MB; a scenario is a few kilobytes");
    return std::nullopt;
  }
  std::optional<SourceNode> root = parse_yaml(text, path.string(), diagnostics);
  if (root && root->is_null()) {
    diagnostics.error({path.string(), 1, 1}, "",
                      "the file holds no YAML value (it is empty, only comments, or null); "
                      "expected a map of keys");
    return std::nullopt;
  }
  return root;
}

void relocate(SourceNode& node, const SourceLocation& where) {
  node.where = where;
  for (SourceNode& item : node.items) relocate(item, where);
  for (SourceNode::Entry& entry : node.entries) {
    entry.key_where = where;
    relocate(entry.value, where);
  }
}

}  // namespace rodsort::scenarios
