#include "geomint/scene/scene.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstdint>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <system_error>

#include <toml++/toml.h>

namespace geomint {

Schema::Schema() = default;
Schema::Schema(const Schema&) = default;
Schema::Schema(Schema&&) noexcept = default;
Schema& Schema::operator=(const Schema&) = default;
Schema& Schema::operator=(Schema&&) noexcept = default;
Schema::~Schema() = default;

namespace {

std::string fmt(double v) {
  if (v == std::floor(v) && std::fabs(v) < 1e15) return std::to_string(static_cast<std::int64_t>(v));  // exact integers
  std::ostringstream s;
  s << v;
  return s.str();
}

// A value as the user would write it (shortest round-trip form for floats).
std::string repr(const toml::node& node) {
  if (const auto* v = node.as_floating_point()) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v->get());
    return std::string(buf, r.ptr);
  }
  if (const auto* v = node.as_integer()) return std::to_string(v->get());
  if (const auto* v = node.as_boolean()) return v->get() ? "true" : "false";
  if (const auto* v = node.as_string()) return '"' + printable(v->get()) + '"';
  if (node.is_date() || node.is_time() || node.is_date_time()) {  // (TOML's own notation, e.g. 1979-05-27)
    std::ostringstream out;
    node.visit([&](const auto& n) { out << n; });
    return out.str() + " (a date or time)";
  }
  if (const auto* arr = node.as_array()) {  // (a long list by its first and last entries, so a refusal stays short)
    constexpr std::size_t head = 3, tail = 2;
    const std::size_t n = arr->size();
    std::string out = "[";
    for (std::size_t i = 0; i < n; ++i) {
      if (n > head + tail + 1 && i == head) {
        out += ", ... (" + std::to_string(n) + " entries)";
        i = n - tail - 1;
        continue;
      }
      out += (i ? ", " : "") + repr(*arr->get(i));
    }
    return out + "]";
  }
  return "(table)";
}

std::vector<std::string> split_dotted(std::string_view key) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = key.find('.', start);
    parts.emplace_back(key.substr(start, dot - start));
    if (dot == std::string_view::npos) break;
    start = dot + 1;
  }
  return parts;
}

// Every leaf (non-table value) of the table as a dotted key.
void leaf_keys(const toml::table& t, const std::string& prefix, std::vector<std::string>& out) {
  for (const auto& [k, v] : t) {
    const std::string key = prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    if (const auto* sub = v.as_table()) {
      leaf_keys(*sub, key, out);
    } else {
      out.push_back(key);
    }
  }
}

}  // namespace

bool Bound::admits(double v) const {
  if (!std::isfinite(v)) return false;
  if (gt && !(v > *gt)) return false;
  if (ge && !(v >= *ge)) return false;
  if (lt && !(v < *lt)) return false;
  if (le && !(v <= *le)) return false;
  return true;
}

std::string Bound::describe() const {
  std::string d = "a finite number";
  std::vector<std::string> parts;
  if (gt) parts.push_back("> " + fmt(*gt));
  if (ge) parts.push_back(">= " + fmt(*ge));
  if (lt) parts.push_back("< " + fmt(*lt));
  if (le) parts.push_back("<= " + fmt(*le));
  for (std::size_t i = 0; i < parts.size(); ++i) d += (i ? " and " : " ") + parts[i];
  return d;
}

std::string type_name(Schema::Type t) {
  switch (t) {
    case Schema::Type::real: return "a number";
    case Schema::Type::integer: return "an integer";
    case Schema::Type::reals: return "a list of numbers";
    case Schema::Type::real_rows: return "a list of lists of numbers";
    case Schema::Type::boolean: return "true or false";
    case Schema::Type::text: return "a string";
    case Schema::Type::texts: return "a list of strings";
  }
  return "?";
}

std::size_t max_entries(const Schema::Entry& e) {
  return e.type == Schema::Type::texts && !e.choices.empty() ? e.choices.size() : max_list_entries;
}

std::string allowed_values(const Schema::Entry& e) {
  using T = Schema::Type;
  std::string a;
  if (e.type == T::real || e.type == T::integer || e.type == T::reals || e.type == T::real_rows) a = e.bound.describe();
  if (e.type == T::reals || e.type == T::texts)
    a += (a.empty() ? "" : "; ") + std::to_string(e.min_len) + " to " + std::to_string(max_entries(e)) + " entries";
  if (e.type == T::real_rows)
    a += "; " + std::to_string(e.min_len) + " to " + std::to_string(max_entries(e)) + " rows of " + std::to_string(e.row_len);
  if (!e.choices.empty()) {
    a += a.empty() ? "one of" : "; each one of";
    for (const auto& c : e.choices) a += " \"" + c + "\"";
  }
  return a;
}

Schema& Schema::alias(std::string old_key, std::string key) {
  aliases_.emplace_back(std::move(old_key), std::move(key));
  return *this;
}

Schema& Schema::add(Entry e) {
  if (find(e.key)) throw std::logic_error("Schema: key declared twice: " + e.key);
  entries_.push_back(std::move(e));
  return *this;
}
Schema& Schema::merge(const Schema& other) {
  for (const auto& e : other.entries_) add(e);
  for (const auto& [old_key, key] : other.aliases_) alias(old_key, key);
  return *this;
}
Schema& Schema::real(std::string key, Bound b, std::string doc) {
  return add({std::move(key), Type::real, b, 0, 0, {}, std::move(doc)});
}
Schema& Schema::integer(std::string key, Bound b, std::string doc) {
  if (!b.lt && !b.le) b.le = static_cast<double>(std::numeric_limits<std::int32_t>::max());  // fits an int
  return add({std::move(key), Type::integer, b, 0, 0, {}, std::move(doc)});
}
Schema& Schema::reals(std::string key, Bound each, std::size_t min_len, std::string doc) {
  return add({std::move(key), Type::reals, each, min_len, 0, {}, std::move(doc)});
}
Schema& Schema::real_rows(std::string key, std::size_t row_len, Bound each, std::size_t min_rows, std::string doc) {
  return add({std::move(key), Type::real_rows, each, min_rows, row_len, {}, std::move(doc)});
}
Schema& Schema::boolean(std::string key, std::string doc) {
  return add({std::move(key), Type::boolean, {}, 0, 0, {}, std::move(doc)});
}
Schema& Schema::text(std::string key, std::vector<std::string> choices, std::string doc) {
  return add({std::move(key), Type::text, {}, 0, 0, std::move(choices), std::move(doc)});
}
Schema& Schema::texts(std::string key, std::vector<std::string> choices, std::size_t min_len, std::string doc) {
  return add({std::move(key), Type::texts, {}, min_len, 0, std::move(choices), std::move(doc)});
}

const Schema::Entry* Schema::find(std::string_view key) const {
  for (const auto& e : entries_)
    if (e.key == key) return &e;
  return nullptr;
}

namespace {

// What is wrong with `node` as a value of `e`, or nothing.
std::optional<std::string> check(const Schema::Entry& e, const toml::node& node) {
  const auto number_ok = [&](const toml::node& n) -> std::optional<std::string> {
    if (!n.is_number()) return std::string("must be ") + (e.type == Schema::Type::real ? "" : "made of ") + e.bound.describe();
    if (!e.bound.admits(*n.value<double>())) return "must be " + e.bound.describe();
    return std::nullopt;
  };
  switch (e.type) {
    case Schema::Type::real:
      return number_ok(node);
    case Schema::Type::integer:
      if (node.is_floating_point())  // (1e3 and 1000.0 are floats in TOML)
        return "must be an integer, " + e.bound.describe() + " (it is written as a floating-point number: TOML reads 1e3 "
               "and 1000.0 as floats; write 1000)";
      if (!node.is_integer()) return "must be an integer, " + e.bound.describe();
      if (!e.bound.admits(static_cast<double>(*node.value<std::int64_t>()))) return "must be an integer, " + e.bound.describe();
      return std::nullopt;
    case Schema::Type::reals: {
      const auto* arr = node.as_array();
      const std::string allowed = "must be a list of " + std::to_string(e.min_len) + " to " + std::to_string(max_entries(e)) +
                                  " numbers, each " + e.bound.describe();
      if (!arr || arr->size() < e.min_len || arr->size() > max_entries(e)) return allowed;
      for (const auto& x : *arr)
        if (number_ok(x)) return allowed;
      return std::nullopt;
    }
    case Schema::Type::real_rows: {
      const auto* arr = node.as_array();
      const std::string allowed = "must be a list of " + std::to_string(e.min_len) + " to " + std::to_string(max_entries(e)) +
                                  " lists of " + std::to_string(e.row_len) + " numbers, each " + e.bound.describe();
      if (!arr || arr->size() < e.min_len || arr->size() > max_entries(e)) return allowed;
      for (const auto& row : *arr) {
        const auto* r = row.as_array();
        if (!r || r->size() != e.row_len) return allowed;
        for (const auto& x : *r)
          if (number_ok(x)) return allowed;
      }
      return std::nullopt;
    }
    case Schema::Type::boolean:
      if (!node.is_boolean()) return std::string("must be true or false");
      return std::nullopt;
    case Schema::Type::text:
    case Schema::Type::texts: {
      const bool list = e.type == Schema::Type::texts;
      std::string allowed = !list ? "must be a string"
                                  : "must be a list of " + std::to_string(e.min_len) + " to " + std::to_string(max_entries(e)) + " strings";
      if (!e.choices.empty()) {
        allowed += list ? ", each one of " : ", one of ";
        for (std::size_t i = 0; i < e.choices.size(); ++i) allowed += (i ? ", \"" : "\"") + e.choices[i] + "\"";
      }
      const auto ok = [&](const toml::node& n) {
        return n.is_string() && (e.choices.empty() || std::find(e.choices.begin(), e.choices.end(),
                                                                n.as_string()->get()) != e.choices.end());
      };
      if (!list) return ok(node) ? std::nullopt : std::optional<std::string>(allowed);
      const auto* arr = node.as_array();
      if (!arr || arr->size() < e.min_len || arr->size() > max_entries(e)) return allowed;
      for (const auto& x : *arr)
        if (!ok(x)) return allowed;
      return std::nullopt;
    }
  }
  return std::nullopt;
}

}  // namespace

namespace {

constexpr int kMaxBaseDepth = 8;
constexpr std::uintmax_t kMaxSceneBytes = 1 << 20;  // a scene file is read whole: the largest one read
constexpr int kMaxKeyDepth = 32;                     // dotted components of a key, and nesting of [ and {

// A path's problem in words (std::error_code from std::filesystem), for a refusal.
std::string path_problem(const std::error_code& ec) {
  if (ec == std::errc::too_many_symbolic_link_levels) return "a loop of symbolic links";
  if (ec == std::errc::filename_too_long) return "the path is too long (a name over 255 bytes, or the whole over PATH_MAX)";
  if (ec == std::errc::no_such_file_or_directory) return "no such file";
  if (ec == std::errc::permission_denied) return "permission denied";
  return ec.message();
}

// Refuses, before the TOML parser recurses into it, a scene whose keys have more than kMaxKeyDepth
// dotted components or whose arrays and inline tables nest deeper than that: a scan of the text that
// skips strings and comments, and counts a '.' as a key's separator where a key is written (at the
// start of a line, in a [table] header, after '{' or ',' in an inline table, up to '=').
void check_scene_shape(const std::string& text, const std::string& where) {
  std::vector<char> open;  // the brackets open at this point
  bool in_key = true;      // (a line starts with a key or a header)
  int components = 1, line = 1;
  const auto refuse = [&](const std::string& what) {
    throw SceneError(where + ":" + std::to_string(line) + ": " + what);
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '"' || c == '\'') {  // a string: skip to its end ("""...""" and '''...''' span lines)
      const std::string quote = text.compare(i, 3, std::string(3, c)) == 0 ? std::string(3, c) : std::string(1, c);
      std::size_t j = i + quote.size();
      for (; j < text.size() && text.compare(j, quote.size(), quote) != 0; ++j) {
        if (c == '"' && text[j] == '\\') ++j;  // (an escape in a basic string)
        if (j < text.size() && text[j] == '\n') ++line;
      }
      i = std::min(text.size(), j + quote.size()) - 1;
    } else if (c == '#') {
      while (i + 1 < text.size() && text[i + 1] != '\n') ++i;
    } else if (c == '\n') {
      ++line;
      if (open.empty()) in_key = true, components = 1;
    } else if (c == '[' || c == '{') {
      open.push_back(c);
      if (open.size() > static_cast<std::size_t>(kMaxKeyDepth)) refuse("arrays or inline tables nested more than " + std::to_string(kMaxKeyDepth) + " deep");
      if (c == '{' || in_key) in_key = true, components = 1;  // (an inline table's first key; a header's key)
    } else if (c == ']' || c == '}') {
      if (!open.empty()) open.pop_back();
      if (open.empty() && c == ']') in_key = false;  // (the end of a header)
    } else if (c == ',' && !open.empty() && open.back() == '{') {
      in_key = true, components = 1;
    } else if (c == '=') {
      in_key = false;
    } else if (c == '.' && in_key && ++components > kMaxKeyDepth) {
      refuse("a key of more than " + std::to_string(kMaxKeyDepth) + " dotted components");
    }
  }
}

// The text of a scene file, checked as a path (who: how the user named it) and for its size and shape.
std::string read_scene_text(const std::filesystem::path& file, const std::string& who) {
  std::error_code ec;
  const auto status = std::filesystem::status(file, ec);
  if (ec && ec != std::errc::no_such_file_or_directory) throw SceneError(who + ": " + path_problem(ec));
  if (!std::filesystem::exists(status)) throw SceneError(who + ": no such file");
  if (std::filesystem::is_directory(status)) throw SceneError(who + ": is a directory, not a scene file");
  if (!std::filesystem::is_regular_file(status))
    throw SceneError(who + ": is not a regular file (a device, a pipe or a socket), not a scene file");
  const auto size = std::filesystem::file_size(file, ec);
  if (ec) throw SceneError(who + ": " + path_problem(ec));
  if (size > kMaxSceneBytes)
    throw SceneError(who + ": is " + std::to_string(size) + " bytes, over the " + std::to_string(kMaxSceneBytes) +
                     " bytes (1 MiB) a scene file may have");
  // Read in pieces, at most one byte past the limit (a file of the proc file system says 0 bytes and may
  // hold more, or fail to be read: its read error is a refusal, not an abort).
  std::string text;
  try {
    std::ifstream in(file, std::ios::binary);
    char buf[65536];
    while (in && text.size() <= kMaxSceneBytes) {
      in.read(buf, sizeof buf);
      text.append(buf, static_cast<std::size_t>(in.gcount()));
    }
    if (!in && !in.eof()) throw SceneError(who + ": cannot be read");
  } catch (const std::ios_base::failure& e) {
    throw SceneError(who + ": cannot be read (" + printable(e.what()) + ")");
  }
  if (text.size() > kMaxSceneBytes)
    throw SceneError(who + ": holds more than the " + std::to_string(kMaxSceneBytes) + " bytes (1 MiB) a scene file may have");
  check_scene_shape(text, printable(file.string()));
  return text;
}

// Moves the value at dotted path `from` to `to` (an older spelling of a key).
// Moves `from` to `to` (an older spelling); returns whether `from` was there.
bool rename_key(toml::table& t, const std::string& from, const std::string& to, const std::string& where) {
  const auto node = t.at_path(from);
  if (!node) return false;
  if (t.at_path(to)) throw SceneError(where + ": '" + from + "' and '" + to + "' are the same key; give only '" + to + "'");
  const auto parts = split_dotted(from), target = split_dotted(to);
  toml::table* parent = &t;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) parent = (*parent)[parts[i]].as_table();
  toml::table* dest = &t;
  for (std::size_t i = 0; i + 1 < target.size(); ++i) {
    if (!(*dest)[target[i]].as_table()) dest->insert_or_assign(target[i], toml::table{});
    dest = (*dest)[target[i]].as_table();
  }
  (*parent)[parts.back()].node()->visit([&](const auto& n) { dest->insert_or_assign(target.back(), n); });
  parent->erase(parts.back());
  return true;
}

// Where a key's value came from, naming the older spelling if that is what was written.
std::string spelled_as(const std::string& origin, const std::string& given, const std::string& key) {
  return given == key ? origin : origin + " as '" + given + "', the older name of '" + key + "'";
}

// Lays `over` onto `base`: tables merge key by key, every other value replaces.
void merge_into(toml::table& base, const toml::table& over) {
  for (const auto& [k, v] : over) {
    auto* sub = base[k].as_table();
    if (const auto* t = v.as_table(); t && sub) {
      merge_into(*sub, *t);
    } else {
      v.visit([&, key = k](const auto& n) { base.insert_or_assign(key, n); });
    }
  }
}

struct Loaded {
  toml::table table;
  std::map<std::string, std::string, std::less<>> origin;
  std::vector<std::filesystem::path> bases;
};

// `who`: how the user named the file ("--scene FILE", or the base of a scene).
Loaded read_scene(const std::filesystem::path& file, const std::string& who, const Schema& schema,
                  std::vector<std::filesystem::path>& chain) {
  const std::string where = printable(file.string());
  const std::string text = read_scene_text(file, who);
  Loaded out;
  toml::table own;
  try {
    own = toml::parse(text, where);
  } catch (const toml::parse_error& err) {
    const auto& b = err.source().begin;
    throw SceneError(where + ":" + std::to_string(b.line) + ":" + std::to_string(b.column) +
                     ": not valid TOML: " + std::string(err.description()));
  }
  std::map<std::string, std::string> spelled;  // new key -> the older spelling this file used
  for (const auto& [from, to] : schema.aliases())
    if (rename_key(own, from, to, where)) spelled[to] = from;
  if (const auto base = own["base"]; base) {
    if (!base.is_string()) throw SceneError(where + ": base must be a string naming the base scene file");
    const std::filesystem::path base_file = file.parent_path() / *base.value<std::string>();
    const std::string base_who = where + ": base = \"" + printable(*base.value<std::string>()) + "\" (" + printable(base_file.string()) + ")";
    std::error_code ec;
    const auto canonical = std::filesystem::weakly_canonical(base_file, ec);
    if (ec) throw SceneError(base_who + ": " + path_problem(ec));
    for (const auto& seen : chain)
      if (seen == canonical) throw SceneError(where + ": base " + base_file.string() + " is already in the chain of bases");
    if (chain.size() >= kMaxBaseDepth) throw SceneError(where + ": more than " + std::to_string(kMaxBaseDepth) + " bases");
    chain.push_back(canonical);
    out = read_scene(base_file, base_who, schema, chain);
    out.bases.insert(out.bases.begin(), base_file);
    own.erase("base");
  }
  std::vector<std::string> keys;
  leaf_keys(own, "", keys);
  for (const auto& key : keys) {
    const auto old = spelled.find(key);
    out.origin[key] = spelled_as("in " + where, old == spelled.end() ? key : old->second, key);
  }
  merge_into(out.table, own);
  return out;
}

}  // namespace

bool key_under(std::string_view key, const std::vector<std::string>& prefixes) {
  for (const auto& p : prefixes)
    if (key == p || (key.size() > p.size() && key.starts_with(p) && key[p.size()] == '.')) return true;
  return false;
}

struct Scene::Table {
  toml::table t;
};

Scene Scene::load(const std::filesystem::path& file, const std::vector<std::string>& overrides,
                  const Schema& schema) {
  Scene scene;
  scene.file_ = file;
  const std::string where = printable(file.string());
  std::error_code ec;
  std::vector<std::filesystem::path> chain{std::filesystem::weakly_canonical(file, ec)};
  if (ec) throw SceneError("--scene " + where + ": " + path_problem(ec));
  Loaded loaded = read_scene(file, "--scene " + where, schema, chain);
  scene.table_ = std::make_shared<Table>(Table{std::move(loaded.table)});
  scene.origin_ = std::move(loaded.origin);
  scene.bases_ = std::move(loaded.bases);

  std::vector<std::string> keys;
  leaf_keys(scene.table_->t, "", keys);
  for (const auto& key : keys) {
    if (!schema.find(key))
      throw SceneError(scene.origin_[key].substr(3) + ": unknown key '" + printable(key) + "' (see --help for the keys)");
  }

  for (const auto& assignment : overrides) {
    const auto eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0) {
      throw SceneError("--set " + assignment + ": expected key=value");
    }
    const std::string given = assignment.substr(0, eq), value = assignment.substr(eq + 1);
    std::string key = given;
    for (const auto& [from, to] : schema.aliases())
      if (key == from) key = to;
    const auto* entry = schema.find(key);
    if (!entry)
      throw SceneError("--set " + printable(key + "=" + value) + ": unknown key '" + printable(key) + "' (see --help for the keys)");
    toml::table parsed;
    try {
      parsed = toml::parse("v = " + value);
    } catch (const toml::parse_error&) {
      throw SceneError("--set " + key + "=" + value + ": cannot read '" + value + "' as " + type_name(entry->type) +
                       " (TOML syntax: 0.1, 1e-3, [0.1, 0.05], true, \"text\")");
    }
    toml::table* t = &scene.table_->t;
    const auto parts = split_dotted(key);
    for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
      if (!(*t)[parts[i]].as_table()) t->insert_or_assign(parts[i], toml::table{});
      t = (*t)[parts[i]].as_table();
    }
    parsed.get("v")->visit([&](const auto& n) { t->insert_or_assign(parts.back(), n); });
    scene.origin_[key] = spelled_as("from --set", given, key);
  }

  for (const auto& e : schema.entries()) {
    const auto node = scene.table_->t.at_path(e.key);
    if (node)
      if (auto why = check(e, *node.node())) scene.reject(e.key, *why);
  }
  return scene;
}

void Scene::require(const std::vector<std::string>& prefixes, std::string_view who, const Schema& schema) const {
  for (const auto& e : schema.entries()) {
    if (!key_under(e.key, prefixes) || table_->t.at_path(e.key)) continue;
    std::string bases;
    for (const auto& b : bases_) bases += ", base " + b.string();
    throw SceneError(file_.string() + bases + ": missing key '" + e.key + "' (" + type_name(e.type) + "), needed by " +
                     std::string(who));
  }
}

void Scene::restrict_reads(std::vector<std::string> prefixes, std::string who) const {
  readable_ = std::move(prefixes);
  reader_ = std::move(who);
}

bool Scene::has(std::string_view key) const { return static_cast<bool>(table_->t.at_path(key)); }

void Scene::reject(std::string_view key, std::string_view allowed) const {
  const auto node = table_->t.at_path(key);
  const std::string value = node ? repr(*node.node()) : "(missing)";
  const auto from = origin_.find(key);
  throw SceneError(std::string(key) + " = " + value + " (" + (from != origin_.end() ? from->second : "in " + file_.string()) +
                   "): " + std::string(allowed));
}

void Scene::note_read(std::string_view key) const {
  if (!readable_.empty() && !key_under(key, readable_))
    throw std::logic_error(reader_ + " reads the scene key '" + std::string(key) + "', which it does not declare");
  if (read_log_ && std::find(read_log_->begin(), read_log_->end(), key) == read_log_->end()) read_log_->emplace_back(key);
}

namespace {

// The node of a key that the studies that run required (Scene::require): its absence is a bug.
const toml::node& required_node(const toml::table& t, std::string_view key) {
  const auto node = t.at_path(key);
  if (!node) throw std::logic_error("Scene: key not present (not required by the studies that run): " + std::string(key));
  return *node.node();
}

template <class T>
std::vector<T> values_of(const toml::node& array) {
  std::vector<T> out;
  for (const auto& x : *array.as_array()) out.push_back(*x.value<T>());
  return out;
}

}  // namespace

template <class T>
T Scene::value(std::string_view key) const {
  note_read(key);
  return *required_node(table_->t, key).value<T>();
}

double Scene::real(std::string_view key) const { return value<double>(key); }
std::int64_t Scene::integer(std::string_view key) const { return value<std::int64_t>(key); }
bool Scene::boolean(std::string_view key) const { return value<bool>(key); }
std::string Scene::text(std::string_view key) const { return value<std::string>(key); }

std::vector<double> Scene::reals(std::string_view key) const {
  note_read(key);
  return values_of<double>(required_node(table_->t, key));
}

std::vector<std::string> Scene::texts(std::string_view key) const {
  note_read(key);
  return values_of<std::string>(required_node(table_->t, key));
}

std::vector<std::vector<double>> Scene::real_rows(std::string_view key) const {
  note_read(key);
  std::vector<std::vector<double>> out;
  for (const auto& row : *required_node(table_->t, key).as_array()) out.push_back(values_of<double>(row));
  return out;
}

nlohmann::ordered_json Scene::to_json() const {
  std::ostringstream s;
  s << toml::json_formatter{table_->t};
  return nlohmann::ordered_json::parse(s.str());
}

}  // namespace geomint
