#include "geomint/scene/scene.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>

namespace geomint {

namespace {

std::string fmt(double v) {
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
  if (const auto* v = node.as_string()) return '"' + v->get() + '"';
  if (const auto* arr = node.as_array()) {
    std::string out = "[";
    for (std::size_t i = 0; i < arr->size(); ++i) out += (i ? ", " : "") + repr(*arr->get(i));
    return out + "]";
  }
  return "(table)";
}

const char* type_name(Schema::Type t) {
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

Schema& Schema::add(Entry e) {
  if (find(e.key)) throw std::logic_error("Schema: key declared twice: " + e.key);
  entries_.push_back(std::move(e));
  return *this;
}
Schema& Schema::real(std::string key, Bound b, std::string doc) {
  return add({std::move(key), Type::real, b, 0, 0, {}, std::move(doc)});
}
Schema& Schema::integer(std::string key, Bound b, std::string doc) {
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
      if (!node.is_integer()) return "must be an integer, " + e.bound.describe();
      if (!e.bound.admits(static_cast<double>(*node.value<std::int64_t>()))) return "must be an integer, " + e.bound.describe();
      return std::nullopt;
    case Schema::Type::reals: {
      const auto* arr = node.as_array();
      const std::string allowed = "must be a list of at least " + std::to_string(e.min_len) + " numbers, each " +
                                  e.bound.describe();
      if (!arr || arr->size() < e.min_len) return allowed;
      for (const auto& x : *arr)
        if (number_ok(x)) return allowed;
      return std::nullopt;
    }
    case Schema::Type::real_rows: {
      const auto* arr = node.as_array();
      const std::string allowed = "must be a list of at least " + std::to_string(e.min_len) + " lists of " +
                                  std::to_string(e.row_len) + " numbers, each " + e.bound.describe();
      if (!arr || arr->size() < e.min_len) return allowed;
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
      std::string allowed = list ? "must be a list of at least " + std::to_string(e.min_len) + " strings" : "must be a string";
      if (!e.choices.empty()) {
        allowed += list ? ", each one of" : ", one of";
        for (const auto& c : e.choices) allowed += " \"" + c + "\"";
      }
      const auto ok = [&](const toml::node& n) {
        return n.is_string() && (e.choices.empty() || std::find(e.choices.begin(), e.choices.end(),
                                                                n.as_string()->get()) != e.choices.end());
      };
      if (!list) return ok(node) ? std::nullopt : std::optional<std::string>(allowed);
      const auto* arr = node.as_array();
      if (!arr || arr->size() < e.min_len) return allowed;
      for (const auto& x : *arr)
        if (!ok(x)) return allowed;
      return std::nullopt;
    }
  }
  return std::nullopt;
}

}  // namespace

Scene Scene::load(const std::filesystem::path& file, const std::vector<std::string>& overrides,
                  const Schema& schema) {
  Scene scene;
  scene.file_ = file;
  const std::string where = file.string();
  if (!std::filesystem::is_regular_file(file)) throw SceneError("--scene " + where + ": no such file");
  try {
    scene.table_ = toml::parse_file(where);
  } catch (const toml::parse_error& err) {
    const auto& b = err.source().begin;
    throw SceneError(where + ":" + std::to_string(b.line) + ":" + std::to_string(b.column) +
                     ": not valid TOML: " + std::string(err.description()));
  }

  std::vector<std::string> keys;
  leaf_keys(scene.table_, "", keys);
  for (const auto& key : keys) {
    if (!schema.find(key)) throw SceneError(where + ": unknown key '" + key + "' (see --help for the keys)");
  }

  for (const auto& assignment : overrides) {
    const auto eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0) {
      throw SceneError("--set " + assignment + ": expected key=value");
    }
    const std::string key = assignment.substr(0, eq);
    const std::string value = assignment.substr(eq + 1);
    const auto* entry = schema.find(key);
    if (!entry) throw SceneError("--set " + key + "=" + value + ": unknown key '" + key + "' (see --help for the keys)");
    toml::table parsed;
    try {
      parsed = toml::parse("v = " + value);
    } catch (const toml::parse_error&) {
      throw SceneError("--set " + key + "=" + value + ": cannot read '" + value + "' as " + type_name(entry->type) +
                       " (TOML syntax: 0.1, 1e-3, [0.1, 0.05], true, \"text\")");
    }
    toml::table* t = &scene.table_;
    const auto parts = split_dotted(key);
    for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
      if (!(*t)[parts[i]].as_table()) t->insert_or_assign(parts[i], toml::table{});
      t = (*t)[parts[i]].as_table();
    }
    parsed.get("v")->visit([&](const auto& n) { t->insert_or_assign(parts.back(), n); });
    scene.overridden_.push_back(key);
  }

  for (const auto& e : schema.entries()) {
    const auto node = scene.table_.at_path(e.key);
    if (!node) throw SceneError(where + ": missing key '" + e.key + "' (" + type_name(e.type) + ")");
    if (auto why = check(e, *node.node())) scene.reject(e.key, *why);
  }
  return scene;
}

void Scene::reject(std::string_view key, std::string_view allowed) const {
  const bool from_set = std::find(overridden_.begin(), overridden_.end(), key) != overridden_.end();
  const auto node = table_.at_path(key);
  const std::string value = node ? repr(*node.node()) : "(missing)";
  throw SceneError(std::string(key) + " = " + value + (from_set ? " (from --set)" : " (in " + file_.string() + ")") +
                   ": " + std::string(allowed));
}

toml::node_view<const toml::node> Scene::at(std::string_view key) const {
  const auto node = table_.at_path(key);
  if (!node) throw std::logic_error("Scene: key not in schema: " + std::string(key));
  return node;
}

double Scene::real(std::string_view key) const { return *at(key).value<double>(); }
std::int64_t Scene::integer(std::string_view key) const { return *at(key).value<std::int64_t>(); }
bool Scene::boolean(std::string_view key) const { return *at(key).value<bool>(); }
std::string Scene::text(std::string_view key) const { return *at(key).value<std::string>(); }

std::vector<double> Scene::reals(std::string_view key) const {
  std::vector<double> out;
  for (const auto& x : *at(key).as_array()) out.push_back(*x.value<double>());
  return out;
}

std::vector<std::string> Scene::texts(std::string_view key) const {
  std::vector<std::string> out;
  for (const auto& x : *at(key).as_array()) out.push_back(*x.value<std::string>());
  return out;
}

std::vector<std::vector<double>> Scene::real_rows(std::string_view key) const {
  std::vector<std::vector<double>> out;
  for (const auto& row : *at(key).as_array()) {
    auto& r = out.emplace_back();
    for (const auto& x : *row.as_array()) r.push_back(*x.value<double>());
  }
  return out;
}

nlohmann::ordered_json Scene::to_json() const {
  std::ostringstream s;
  s << toml::json_formatter{table_};
  return nlohmann::ordered_json::parse(s.str());
}

}  // namespace geomint
