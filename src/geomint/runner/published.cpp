#include "geomint/runner/published.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <map>
#include <string_view>

#include <toml++/toml.h>

#include "geomint/io/csv.hpp"

namespace geomint {

namespace {

using json = nlohmann::ordered_json;

const std::vector<std::string> kFields = {"study", "figure", "value", "where", "summary", "compare", "requires", "expect",
                                          "note", "test", "kind", "chosen", "quotes", "roundoff",
                                          "corrected", "stderr", "why"};
const std::vector<std::string> kKinds = {"printed", "scanning", "authors_code", "convention", "sample"};

bool is_claim(const std::string& compare) { return compare == "above" || compare == "below"; }

// A statement of the text rather than a figure or table: "004 Sec. 1.4", "000 eq. (16)".
bool is_text_item(const std::string& figure) {
  return figure.size() > 4 && (figure.compare(4, 4, "Sec.") == 0 || figure.compare(4, 3, "eq.") == 0);
}

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& key, const std::string& what) {
  throw PublishedError(file.string() + ": [" + key + "]: " + what);
}

// A TOML number, string or boolean, or (for `requires`) an array of them, as JSON.
json scalar(const toml::node& n, const std::filesystem::path& file, const std::string& key, bool arrays = false) {
  if (const auto* a = n.as_array(); a && arrays) {
    json out = json::array();
    for (const auto& x : *a) out.push_back(scalar(x, file, key));
    return out;
  }
  if (const auto i = n.as_integer()) return i->get();  // (an order stays an integer)
  if (const auto v = n.value<double>(); v && n.is_floating_point()) {
    if (!std::isfinite(*v)) fail(file, key, "values must be finite numbers");
    return *v;
  }
  if (const auto s = n.value<std::string>()) return *s;
  if (const auto b = n.value<bool>()) return *b;
  fail(file, key, "values must be numbers, strings or booleans");
}

std::string text(const toml::table& t, const char* field, const std::filesystem::path& file, const std::string& key,
                 bool required) {
  const auto n = t[field];
  if (!n) {
    if (required) fail(file, key, std::string("missing '") + field + "'");
    return {};
  }
  if (!n.is_string()) fail(file, key, std::string("'") + field + "' must be a string");
  return *n.value<std::string>();
}

double parameter(const std::string& s) {  // a key of a value table, read as a number
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  return (end && *end == '\0' && end != s.c_str()) ? v : std::nan("");
}

// |reproduced - published| relative to |published| for "rel", absolute otherwise.
double difference(const std::string& compare, double published, double reproduced) {
  const double d = reproduced - published;
  return compare == "rel" ? d / std::abs(published) : d;
}

}  // namespace

double half_unit_in_last_digit(std::string literal) {
  literal.erase(std::remove(literal.begin(), literal.end(), '_'), literal.end());
  const std::size_t e = literal.find_first_of("eE");
  const std::string mantissa = literal.substr(0, e);
  const int exponent = e == std::string::npos ? 0 : std::stoi(literal.substr(e + 1));
  const std::size_t dot = mantissa.find('.');
  const int decimals = dot == std::string::npos ? 0 : static_cast<int>(mantissa.size() - dot - 1);
  return 0.5 * std::pow(10.0, exponent - decimals);
}

const json* json_at(const json& j, const std::string& dotted) {
  const json* node = &j;
  std::string_view rest = dotted;
  while (!rest.empty()) {
    const std::size_t dot = rest.find('.');
    const std::string part(rest.substr(0, dot));
    rest = dot == std::string_view::npos ? std::string_view{} : rest.substr(dot + 1);
    if (node->is_object()) {
      const auto it = node->find(part);
      if (it == node->end()) return nullptr;
      node = &*it;
    } else if (node->is_array()) {
      const double i = parameter(part);
      if (!(i >= 0 && i == std::floor(i) && i < static_cast<double>(node->size()))) return nullptr;
      node = &(*node)[static_cast<std::size_t>(i)];
    } else {
      return nullptr;
    }
  }
  return node;
}

std::vector<Published> read_published(const std::filesystem::path& file) {
  toml::table doc;
  try {
    doc = toml::parse_file(file.string());
  } catch (const toml::parse_error& err) {
    throw PublishedError(file.string() + ":" + std::to_string(err.source().begin.line) + ": not valid TOML: " +
                         std::string(err.description()));
  }
  std::vector<std::string> lines;  // (the values' literals, for a tolerance from the printed digits)
  {
    std::ifstream in(file);
    for (std::string l; std::getline(in, l);) lines.push_back(l);
  }
  // The literal of a number as written in the file (toml++'s source region of its node).
  const auto literal_of = [&](const toml::node& n, const std::string& key) {
    const auto& r = n.source();
    if (r.begin.line == 0 || r.begin.line != r.end.line || r.begin.line > lines.size() || r.end.column <= r.begin.column)
      fail(file, key, "the printed digits of a value could not be read from the file");
    return lines[r.begin.line - 1].substr(r.begin.column - 1, r.end.column - r.begin.column);
  };
  std::vector<std::pair<std::uint32_t, Published>> by_line;  // (toml++ iterates a table by key)
  for (const auto& [k, node] : doc) {
    const std::string key(k.str());
    const auto* t = node.as_table();
    if (!t) fail(file, key, "each published quantity is a table");
    for (const auto& [field, _] : *t)
      if (std::find(kFields.begin(), kFields.end(), std::string(field.str())) == kFields.end())
        fail(file, key, "unknown field '" + std::string(field.str()) + "'");
    Published p;
    p.key = key;
    p.study = text(*t, "study", file, key, true);
    p.where = text(*t, "where", file, key, true);
    p.figure = text(*t, "figure", file, key, false);
    p.summary = text(*t, "summary", file, key, true);
    p.note = text(*t, "note", file, key, false);
    p.test = text(*t, "test", file, key, false);
    p.why = text(*t, "why", file, key, false);
    if (const std::string e = text(*t, "expect", file, key, false); !e.empty()) {
      if (e != "reproduced" && e != "differs") fail(file, key, "expect must be \"reproduced\" or \"differs\"");
      p.expect = e;
    }
    if (p.expect == "differs" && (p.note.empty() || p.test.empty()))
      fail(file, key, "a known discrepancy (expect = \"differs\") needs its note and the ctest test that shows it");
    if (const std::string kd = text(*t, "kind", file, key, false); !kd.empty()) {
      if (std::find(kKinds.begin(), kKinds.end(), kd) == kKinds.end())
        fail(file, key, "kind is \"printed\", \"scanning\", \"authors_code\", \"convention\" or \"sample\"");
      p.kind = kd;
    }
    if ((p.kind == "convention" || p.kind == "sample") && p.note.empty())
      fail(file, key, "a " + p.kind + " needs its note (what the paper leaves open)");
    if (const auto q = (*t)["quotes"]) {  // [{ at = "Sect. 1.4", text = "the paper's words" }, ...]
      const char* form = "quotes is a list of { at = \"where in the paper\", text = \"its words\" }";
      const auto* qa = q.as_array();
      if (!qa || qa->empty()) fail(file, key, form);
      for (const auto& item : *qa) {
        const auto* qt = item.as_table();
        if (!qt || qt->size() != 2 || !(*qt)["at"].is_string() || !(*qt)["text"].is_string()) fail(file, key, form);
        p.quotes.push_back({{"at", *(*qt)["at"].value<std::string>()}, {"text", *(*qt)["text"].value<std::string>()}});
      }
    }
    // A convention is a statement that holds under an assumption the paper makes in the same passage:
    // that passage is quoted.
    if (p.kind == "convention" && p.quotes.empty())
      fail(file, key, "a convention needs quotes: the passage that makes the assumption under which it holds");
    if (p.expect == "differs" && (p.kind == "printed" || p.kind == "scanning") && p.quotes.empty())
      fail(file, key, "a printed statement that differs needs quotes: the paper's words it contradicts");
    if (const auto c = (*t)["chosen"]) {
      const auto* ct = c.as_table();
      if (!ct || ct->empty()) fail(file, key, "chosen is a table of scene keys and their printed values");
      for (const auto& [sk, sv] : *ct) p.chosen[std::string(sk.str())] = scalar(sv, file, key);
      if (p.note.empty()) fail(file, key, "a chosen parameter needs its note (why not the printed value)");
    }
    if (const auto c = (*t)["corrected"]) {
      const char* form = "corrected is { what = \"...\", printed = \"...\", used = \"...\", printed_gives = \"<key>\" }";
      const auto* ct = c.as_table();
      if (!ct || ct->size() != 4) fail(file, key, form);
      for (const char* f : {"what", "printed", "used", "printed_gives"}) {
        if (!(*ct)[f].is_string()) fail(file, key, form);
        p.corrected[f] = *(*ct)[f].value<std::string>();
      }
      if (p.note.empty()) fail(file, key, "a corrected coefficient needs its note (why not the printed one)");
    }
    const auto value = (*t)["value"];
    const auto compare_node = (*t)["compare"];
    const bool claim = compare_node && compare_node.as_table() && compare_node.as_table()->size() == 1 &&
                       is_claim(std::string(compare_node.as_table()->cbegin()->first.str()));
    if (claim && value) fail(file, key, "a claim ({ above = x } or { below = x }) has no 'value': the bound is x");
    if (!value && !claim) fail(file, key, "missing 'value'");
    if (claim) {
      // (set below, with the bound)
    } else if (const auto* vt = value.as_table()) {
      p.value = json::object();
      for (const auto& [param, v] : *vt) p.value[std::string(param.str())] = scalar(v, file, key);
    } else {
      p.value = scalar(*value.node(), file, key);
    }
    if (const auto c = compare_node) {
      const char* forms = "compare is { rel = x }, { abs = x } or { order = x } with a finite x >= 0, or a claim "
                          "{ above = x } or { below = x } with a finite x";
      const auto* ct = c.as_table();
      if (!ct || ct->size() != 1) fail(file, key, forms);
      const auto first = ct->cbegin();
      p.compare = std::string(first->first.str());
      const bool printed = (p.compare == "rel" || p.compare == "abs") && first->second.value<std::string>() == "printed";
      const bool from_stderr = p.compare == "abs" && first->second.value<std::string>() == "stderr";
      if (from_stderr) {
        if (!(*t)["stderr"].is_string()) fail(file, key, "{ abs = \"stderr\" } needs stderr = \"<summary path>\"");
        p.tolerance_origin = "stderr", p.stderr_path = *(*t)["stderr"].value<std::string>();
      }
      const auto tv = printed || from_stderr ? std::optional<double>(0.0) : first->second.value<double>();
      if ((p.compare != "rel" && p.compare != "abs" && p.compare != "order" && !claim) || !tv || !std::isfinite(*tv) ||
          (!claim && !(*tv >= 0)))
        fail(file, key, forms);
      p.tolerance = *tv;
      if (printed) {  // half a unit in the last printed digit of each value (relative: of that value)
        p.tolerance_origin = "printed";
        const auto of = [&](const toml::node& n, double v) {
          const std::string literal = literal_of(n, key);
          if (literal.find_first_not_of("+-0123456789._eE") != std::string::npos)
            fail(file, key, "\"printed\" needs each value written in decimal, not " + literal);
          const double half = half_unit_in_last_digit(literal);
          return p.compare == "rel" ? half / std::abs(v) : half;
        };
        if (const auto* vt = value.as_table()) {
          p.tolerances = json::object();
          for (const auto& [param, v] : *vt) p.tolerances[std::string(param.str())] = of(v, *v.value<double>());
        } else {
          p.tolerances = of(*value.node(), *value.value<double>());
        }
      }
      if (claim) p.value = std::string(p.compare == "above" ? "> " : "< ") + json(*tv).dump();
      if (claim && (*t)["stderr"]) {  // the measured quantity beyond the bound by kStandardErrors standard errors
        if (!(*t)["stderr"].is_string()) fail(file, key, "stderr is a summary path (\"<summary path>\")");
        p.tolerance_origin = "stderr", p.stderr_path = *(*t)["stderr"].value<std::string>();
      }
      const auto numeric = [](const json& v) { return v.is_number(); };
      if (!claim && !(p.value.is_number() ||
            (p.value.is_object() && std::all_of(p.value.begin(), p.value.end(), numeric))))
        fail(file, key, "a compared value is a number or a table of numbers");
      if (p.compare == "rel" && p.value.is_number() && p.value.get<double>() == 0.0)
        fail(file, key, "a relative comparison needs a published value != 0 (use abs)");
    }
    // A typed number is a tolerance nobody derived unless its origin is stated (an exact comparison,
    // tolerance 0, needs none); a derived one ("printed", "stderr") states its own. A claim's bound is
    // always typed (its margin may be derived: stderr).
    const bool typed = claim || (!p.compare.empty() && p.tolerance_origin == "typed" && p.tolerance != 0);
    if (typed && p.why.empty())
      fail(file, key, "a typed tolerance needs why = \"...\": where the number " + json(p.tolerance).dump() +
                          " comes from (or derive it: \"printed\", \"stderr\")");
    if (!typed && !p.why.empty()) fail(file, key, "why states the origin of a typed tolerance or bound; this entry has none");
    if (const auto r = (*t)["roundoff"]) {
      const auto* rt = r.as_table();
      if (!rt || !(*rt)["floor"].is_string() || rt->size() > 2 || (rt->size() == 2 && !(*rt)["exact"].is_string()))
        fail(file, key, "roundoff is { floor = \"summary path\" } or { floor = \"...\", exact = \"...\" }");
      p.roundoff_floor = *(*rt)["floor"].value<std::string>();
      if (rt->size() == 2) p.roundoff_exact = *(*rt)["exact"].value<std::string>();
    }
    // A typed absolute tolerance judges a printed value only if it is smaller than it (else the value is
    // round-off for this comparison: declare roundoff, or derive the tolerance from the printed digits).
    if (p.compare == "abs" && p.tolerance_origin == "typed" && p.roundoff_floor.empty())
      for (const json& v : p.value.is_object() ? std::vector<json>(p.value.begin(), p.value.end()) : std::vector<json>{p.value})
        if (v.is_number() && v.get<double>() != 0.0 && !(p.tolerance < std::abs(v.get<double>())))
          fail(file, key, "the absolute tolerance " + json(p.tolerance).dump() + " is not smaller than the value " +
                              v.dump() + " it judges: derive it ({ abs = \"printed\" }) or declare the round-off floor");
    if (const auto r = (*t)["requires"]) {
      const auto* rt = r.as_table();
      if (!rt) fail(file, key, "requires is a table of scene keys and values");
      for (const auto& [sk, sv] : *rt) p.requires_[std::string(sk.str())] = scalar(sv, file, key, true);
    }
    by_line.emplace_back(node.source().begin.line, std::move(p));
  }
  std::stable_sort(by_line.begin(), by_line.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Published> out;
  for (auto& [line, p] : by_line) out.push_back(std::move(p));
  for (const Published& p : out)  // (what the printed coefficient gives is an entry of the same file)
    if (!p.corrected.is_null() && std::none_of(out.begin(), out.end(), [&](const Published& q) {
          return q.key == p.corrected["printed_gives"].get<std::string>();
        }))
      fail(file, p.key, "corrected.printed_gives names no entry of this file");
  return out;
}

std::optional<json> compare_published(const Published& e, const json& summary, const json& scene,
                                      const std::vector<std::string>& studies_ran) {
  if (std::find(studies_ran.begin(), studies_ran.end(), e.study) == studies_ran.end()) return std::nullopt;
  const json* reproduced = json_at(summary, e.summary);
  json c = {{"study", e.study}};
  if (!e.figure.empty()) c["figure"] = e.figure;
  c["where"] = e.where, c["published"] = e.value, c["reproduced"] = reproduced ? *reproduced : json(nullptr);
  if (!e.compare.empty())
    c["compare"] = {{e.compare, e.tolerance_origin == "typed" || is_claim(e.compare) ? json(e.tolerance)
                                                                                      : json(e.tolerance_origin)}};
  if (!e.why.empty()) c["why"] = e.why;  // where a typed tolerance or bound comes from
  if (e.tolerance_origin == "printed") c["tolerances"] = e.tolerances;  // per value: half a unit in its last printed digit
  double stderr_tolerance = 0;  // "stderr": kStandardErrors of the run's standard error
  if (e.tolerance_origin == "stderr") {
    const json* se = json_at(summary, e.stderr_path);
    if (se && se->is_number()) {
      stderr_tolerance = kStandardErrors * se->get<double>();
      c["tolerances"] = {{"standard_error", *se}, {"standard_errors", kStandardErrors}, {"of", stderr_tolerance},
                         {"from", e.stderr_path}};
    }
  }
  if (e.kind != "printed") c["kind"] = e.kind;
  if (!e.quotes.empty()) c["quotes"] = e.quotes;
  if (!e.corrected.is_null()) c["corrected"] = e.corrected;
  for (const auto& [key, printed] : e.chosen.items()) {
    const json* used = json_at(scene, key);
    c["chosen"][key] = {{"printed", printed}, {"used", used ? *used : json(nullptr)}};
  }
  const auto done = [&](const std::string& verdict, const std::string& reason) {
    c["verdict"] = verdict;
    if (!reason.empty()) c["reason"] = reason;
    if (e.expect != "reproduced") c["expect"] = e.expect;
    if (!e.note.empty()) c["note"] = e.note;
    if (!e.test.empty()) c["test"] = e.test;
    return c;
  };
  // The pairs (published, reproduced) to compare: one, or one per parameter of a value table, keyed as
  // the reproduced values are: a name (a method's label) exactly, a number (e.g. h, written as %.17g)
  // by its value. A parameter the run did not compute (a method the scene does not name) is listed.
  std::vector<std::pair<std::string, std::pair<double, const json*>>> pairs;
  std::map<std::string, std::string> printed_param;  // a value table's reproduced key -> its key in published.toml
  json missing = json::array();
  if (is_claim(e.compare) && reproduced) {  // the bound against the value, or every value of a table
    if (reproduced->is_object()) {
      for (const auto& [rk, rv] : reproduced->items()) pairs.push_back({rk, {e.tolerance, &rv}});
    } else {
      pairs.push_back({"", {e.tolerance, reproduced}});
    }
  } else if (e.value.is_number() && reproduced) {
    pairs.push_back({"", {e.value.get<double>(), reproduced}});
  } else if (e.value.is_object()) {
    json published = json::object();
    for (const auto& [param, v] : e.value.items()) {
      const json* r = nullptr;
      std::string at = param;
      if (reproduced && reproduced->is_object())
        for (const auto& [rk, rv] : reproduced->items()) {
          const double a = parameter(rk), b = parameter(param);
          if (rk == param || (!std::isnan(b) && std::abs(a - b) <= 1e-12 * std::abs(b))) r = &rv, at = rk;
        }
      published[at] = v;
      if (!r) missing.push_back(param);
      else if (v.is_number()) pairs.push_back({at, {v.get<double>(), r}}), printed_param[at] = param;
    }
    c["published"] = published;
    if (!missing.empty() && reproduced) c["not_computed"] = missing;
  }
  std::string why_not;  // why the scene does not allow the comparison
  for (const auto& [key, wanted] : e.requires_.items()) {
    const json* actual = json_at(scene, key);
    if (!actual || *actual != wanted)
      why_not += (why_not.empty() ? "" : "; ") + key + " = " + (actual ? actual->dump() : "(none)") + ", published at " +
                 wanted.dump();
  }
  if (!why_not.empty()) return done("not comparable", why_not);
  if (!reproduced) return done("not computed", "this scene computes no " + e.summary);  // e.g. other methods named
  if (e.value.is_object() && missing.size() == e.value.size())
    return done("not computed", "this scene computes " + e.summary + " for none of the published parameters");
  if (e.compare.empty()) return done("reported", "");
  // Entries that measure round-off (the run's floor of the quantity above its exact value, or above both
  // values): not comparable, each; the others are compared.
  json roundoff = json::array();
  if (!e.roundoff_floor.empty()) {
    const json* floor = json_at(summary, e.roundoff_floor);
    const json* exact = e.roundoff_exact.empty() ? nullptr : json_at(summary, e.roundoff_exact);
    if (!floor || (!e.roundoff_exact.empty() && !exact))
      throw PublishedError("[" + e.key + "]: the run wrote no " + (floor ? e.roundoff_exact : e.roundoff_floor));
    const auto at = [](const json* j, const std::string& param) {  // (keyed as the reproduced values)
      const json* v = param.empty() ? j : j->is_object() && j->contains(param) ? &(*j)[param] : nullptr;
      return v && v->is_number() ? v->get<double>() : std::nan("");
    };
    std::erase_if(pairs, [&](const std::pair<std::string, std::pair<double, const json*>>& pr) {
      const auto& [param, values] = pr;
      const double f = at(floor, param);
      const bool is_roundoff = exact ? std::abs(at(exact, param)) <= f
                                     : std::abs(values.first) <= f && values.second->is_number() &&
                                           std::abs(values.second->get<double>()) <= f;
      if (is_roundoff) roundoff.push_back(param);
      return is_roundoff;
    });
    if (!roundoff.empty()) c["roundoff"] = roundoff;
    if (pairs.empty())
      return done("not comparable", "round-off: " + std::string(exact ? "the value in exact arithmetic lies"
                                                                       : "the printed and the reproduced values lie") +
                                        " at or below the run's round-off floor (" + e.roundoff_floor + ")");
  }
  const auto tolerance_at = [&](const std::string& param) {
    if (e.tolerance_origin == "typed") return e.tolerance;
    if (e.tolerance_origin == "stderr") return stderr_tolerance > 0 ? stderr_tolerance : std::nan("");
    const json& t = param.empty() ? e.tolerances : e.tolerances.at(printed_param.at(param));
    return t.get<double>();
  };
  // A claim with stderr: beyond its bound by kStandardErrors standard errors of the run (NaN without them: not held).
  const double claim_margin = e.tolerance_origin != "stderr" ? 0.0 : stderr_tolerance > 0 ? stderr_tolerance : std::nan("");
  bool within = !pairs.empty();
  json diff = pairs.size() == 1 && pairs[0].first.empty() ? json() : json::object();
  for (const auto& [param, pr] : pairs) {
    const auto& [pub, rep] = pr;
    // A reproduced value that is not a finite number is never within any tolerance.
    const double r = rep->is_number() ? rep->get<double>() : std::nan("");
    const double d = is_claim(e.compare) ? r - pub : difference(e.compare, pub, r);  // (a claim: from its bound)
    within = within && std::isfinite(d) &&
             (e.compare == "above" ? d > claim_margin : e.compare == "below" ? d < -claim_margin
                                                                              : std::abs(d) <= tolerance_at(param));
    const json dj = std::isfinite(d) ? json(d) : json(nullptr);
    if (param.empty()) diff = dj;
    else diff[param] = dj;
  }
  c["difference"] = diff;
  return done(within ? "reproduced" : "differs", "");
}

void apply_published(const std::vector<Published>& entries, json& summary, const json& scene,
                     const std::vector<std::string>& studies_ran) {
  for (const Published& e : entries) {
    auto c = compare_published(e, summary, scene, studies_ran);
    if (!c) continue;
    // summary.published: the values this run was set against (not those its scene cannot compare).
    const std::string verdict = (*c)["verdict"];
    if (verdict != "not comparable" && verdict != "not computed") summary["published"][e.key] = (*c)["published"];
    summary["comparisons"][e.key] = std::move(*c);
  }
}

json figure_verdict(const json& comparisons, const std::string& figure) {
  json f = json::object();
  std::vector<std::string> reproduced, differs, unexpected, reported, not_comparable, conventions;
  json chosen = json::object(), corrected = json::object();
  for (const auto& [key, c] : comparisons.items()) {
    if (c.value("figure", "") != figure) continue;
    const std::string v = c.value("verdict", "");
    if (c.value("kind", "printed") == "convention") {
      conventions.push_back(key);
    } else if (v == "reproduced" || v == "differs") {
      (v == "reproduced" ? reproduced : differs).push_back(key);
      if (v == "differs" && c.value("expect", "reproduced") != "differs") unexpected.push_back(key);
      if (c.contains("chosen"))
        for (const auto& [sk, ch] : c["chosen"].items()) chosen[sk] = ch;
      if (c.contains("corrected")) corrected[c["corrected"]["what"].get<std::string>()] = c["corrected"];
    } else if (v == "reported") {
      reported.push_back(key);
    } else if (v == "not comparable") {
      not_comparable.push_back(key);
    }
  }
  std::string verdict;
  if (!reproduced.empty() && differs.empty())
    verdict = chosen.empty() && corrected.empty() ? "reproduced"
              : std::string("reproduced with a corrected ") +
                    (corrected.empty() ? "parameter" : chosen.empty() ? "coefficient" : "parameter and coefficient");
  else if (!reproduced.empty())
    verdict = "partly reproduced";
  else if (!differs.empty())
    verdict = "differs";
  else
    verdict = not_comparable.empty() ? "no printed value" : "not comparable";
  f["verdict"] = verdict;
  const auto list = [&](const char* name, const std::vector<std::string>& keys) {
    if (!keys.empty()) f[name] = keys;
  };
  list("reproduced", reproduced), list("differs", differs), list("unexpected", unexpected);
  list("reported", reported), list("not_comparable", not_comparable), list("conventions", conventions);
  if (!chosen.empty()) f["chosen"] = chosen;
  if (!corrected.empty()) f["corrected"] = corrected;
  return f;
}

void apply_figure_verdicts(json& summary, const std::vector<std::string>& made) {
  json figures = json::object();  // (built apart: adding to summary moves its members)
  const json none = json::object();
  const json& comparisons = summary.contains("comparisons") ? summary["comparisons"] : none;
  for (const std::string& item : made) figures[item] = figure_verdict(comparisons, item);
  summary["figures"] = std::move(figures);
}

void resolve_figures(std::vector<Published>& entries, const std::filesystem::path& file,
                     const std::function<std::vector<std::string>(const std::string&)>& items_of) {
  for (Published& p : entries) {
    const auto items = items_of(p.study);
    std::string makes;
    for (const auto& item : items) makes += (makes.empty() ? "" : ", ") + item;
    if (p.figure.empty()) {
      if (items.size() > 1)
        fail(file, p.key, "figure = ? (study " + p.study + " makes " + makes + ": say which of them it belongs to)");
      if (items.size() == 1) p.figure = items[0];
    } else if (std::find(items.begin(), items.end(), p.figure) == items.end() && !is_text_item(p.figure)) {
      fail(file, p.key, "figure = \"" + p.figure + "\" is not one the study " + p.study + " makes (" +
                            (items.empty() ? std::string("none of the papers' figures") : makes) + ")");
    }
  }
}

}  // namespace geomint
