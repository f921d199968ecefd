#include "reports/gnuplot_svg.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

#include "reports/html.h"

extern char** environ;

namespace ivv::reports {
namespace {

namespace fs = std::filesystem;
using verification::Plot;
using verification::Series;

// A gnuplot single-quoted string: only ' needs escaping (as '').
std::string quoted(const std::string& s) {
  std::string out = "'";
  for (char ch : s) {
    if (ch == '\'')
      out += "''";
    else if (ch == '\n')
      out += ' ';
    else
      out += ch;
  }
  return out + "'";
}

bool is_alnum(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
}
bool is_letter(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}

// The Greek letter a whole word names ("zeta" -> "ζ"), or empty.
std::string greek(const std::string& word) {
  static const std::pair<const char*, const char*> names[] = {
      {"alpha", "α"},  {"beta", "β"}, {"gamma", "γ"}, {"delta", "δ"}, {"zeta", "ζ"},
      {"lambda", "λ"}, {"mu", "μ"},   {"nu", "ν"},    {"xi", "ξ"},    {"rho", "ρ"},
      {"sigma", "σ"},  {"tau", "τ"},  {"omega", "ω"}};
  for (const auto& [name, letter] : names)
    if (word == name) return letter;
  return {};
}

// A word of letters and digits: a Greek name, or a one-letter symbol (Latin or a Greek name)
// followed by 0 (v0, omega0), typeset.
std::string enhanced_word(const std::string& w) {
  if (std::string g = greek(w); !g.empty()) return g;
  if (w.size() >= 2 && w.back() == '0') {
    const std::string stem = w.substr(0, w.size() - 1);
    if (std::string g = greek(stem); !g.empty()) return g + "_{0}";
    if (stem.size() == 1 && is_letter(stem[0])) return stem + "_{0}";
  }
  return w;
}

// The byte length of the UTF-8 code point that starts with `lead`.
std::size_t utf8_length(unsigned char lead) {
  return lead >= 0xF0 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC0 ? 2 : 1;
}

// The group after a ^ or _ at s[i]: {...}, (...) for a superscript, or a run of letters and
// digits (a superscript may start with a minus sign). Returns the typeset group and moves i
// past it; empty (i unchanged) when no group follows.
std::string script_group(const std::string& s, std::size_t& i) {
  const char mark = s[i];
  std::size_t j = i + 1;
  if (j < s.size() && (s[j] == '{' || (mark == '^' && s[j] == '('))) {
    const char open = s[j], close = open == '{' ? '}' : ')';
    int depth = 0;
    for (std::size_t k = j; k < s.size(); ++k) {
      depth += s[k] == open ? 1 : s[k] == close ? -1 : 0;
      if (depth == 0) {
        const std::string inner = s.substr(j + 1, k - j - 1);
        i = k + 1;
        return std::string(1, mark) + "{" + enhanced_text(inner) + "}";
      }
    }
    return {};
  }
  std::size_t k = j;
  if (mark == '^' && k < s.size() && s[k] == '-') ++k;
  while (k < s.size() && (is_alnum(s[k]) || (mark == '^' && s[k] == '.'))) ++k;
  if (k == j || (k == j + 1 && s[j] == '-')) return {};
  const std::string group = s.substr(j, k - j);
  i = k;
  return std::string(1, mark) + "{" + group + "}";
}

bool drawable(double x, double y, const Plot& p) {
  if (!std::isfinite(x) || !std::isfinite(y)) return false;
  if (p.log_x && x <= 0) return false;
  if (p.log_y && y <= 0) return false;
  return true;
}

// The series' datablock body; empty when no point is drawable.
std::string data_block(const Series& s, const Plot& p) {
  std::string out;
  bool any = false, gap = false;
  const std::size_t n = std::min(s.x.size(), s.y.size());
  char line[80];
  for (std::size_t i = 0; i < n; ++i) {
    if (!drawable(s.x[i], s.y[i], p)) {
      gap = any;
      continue;
    }
    if (gap) out += "\n";  // a blank line breaks the curve
    gap = false;
    any = true;
    if (s.style == Series::Style::error_bars)
      std::snprintf(line, sizeof line, "%.10g %.10g %.10g\n", s.x[i], s.y[i],
                    i < s.y_error.size() ? s.y_error[i] : 0.0);
    else
      std::snprintf(line, sizeof line, "%.10g %.10g\n", s.x[i], s.y[i]);
    out += line;
  }
  return any ? out : std::string();
}

// The plot clause's style for the series at `index` of its plot. Colour: one of the 8
// linetypes, by index; from the ninth series on, the colours repeat and the line changes (a
// dash-dot line for solid ones, dots for dashed ones). Markers: open ones for point-only
// series, so that coinciding points stay visible; no two of the first 15 series share both
// colour and marker. So up to 15 series differ from each other in colour, line or marker.
std::string style(Series::Style s, int index) {
  // gnuplot point types: 7/5/9/11/13/15 filled circle/square/triangles/diamond/pentagon,
  // 6/4/8/10/12/14 the same open, 1/2/3 plus, cross, star
  // From the tenth series on the colours have come round: the same fill, another shape than
  // the series of the same colour had.
  static constexpr int kFilled[] = {7, 5, 9, 11, 13, 15, 1, 2, 3, 9, 11, 13, 15, 7, 5};
  static constexpr int kOpen[] = {6, 4, 8, 10, 12, 14, 1, 2, 3, 8, 10, 12, 14, 6, 4};
  constexpr int kMarkers = static_cast<int>(std::size(kFilled));
  const bool second_cycle = index >= 8;
  const std::string t = " lt " + std::to_string(index % 8 + 1);
  const std::string filled = std::to_string(kFilled[index % kMarkers]);
  const std::string open = std::to_string(kOpen[index % kMarkers]);
  const std::string solid = second_cycle ? " dt (12,4,2,4)" : "";
  switch (s) {
    case Series::Style::lines:
      return "with lines" + t + " lw 2" + solid;
    case Series::Style::points:
      return "with points" + t + " pt " + open + " ps 0.8";
    case Series::Style::linespoints:
      return "with linespoints" + t + " lw 1.5" + solid + " pt " + filled + " ps 0.55";
    case Series::Style::dashed:
      return "with lines" + t + " lw 2 dt " + (second_cycle ? "(3,4)" : "(8,5)");
    case Series::Style::error_bars:
      return "with yerrorbars" + t + " pt " + filled + " ps 0.5";
  }
  return "with lines" + t;
}

struct TempDir {
  fs::path path;
  TempDir() {
    std::string tmpl = (fs::temp_directory_path() / "ivv-gnuplot-XXXXXX").string();
    if (!mkdtemp(tmpl.data()))
      throw std::runtime_error("cannot create a temporary directory for gnuplot in " +
                               fs::temp_directory_path().string());
    path = tmpl;
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
};

std::string read_all(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Runs `argv` with stdout and stderr sent to files; returns the exit status (-1: not run).
int run_process(const std::vector<std::string>& argv, const fs::path& out, const fs::path& err) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) return -1;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return -1;
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

void replace_all(std::string& s, const std::string& from, const std::string& to) {
  for (std::size_t pos = s.find(from); pos != std::string::npos;
       pos = s.find(from, pos + to.size()))
    s.replace(pos, from.size(), to);
}

// Labels of the series that gnuplot_script() draws, in plot order.
std::vector<std::string> drawn_labels(const Plot& plot) {
  std::vector<std::string> labels;
  for (const auto& s : plot.series)
    if (!data_block(s, plot).empty()) labels.push_back(s.label);
  return labels;
}

}  // namespace

std::string enhanced_text(const std::string& s) {
  std::string out;
  std::size_t i = 0;
  while (i < s.size()) {
    const char c = s[i];
    const auto lead = static_cast<unsigned char>(c);
    if (is_alnum(c)) {
      std::size_t j = i;
      while (j < s.size() && is_alnum(s[j])) ++j;
      out += enhanced_word(s.substr(i, j - i));
      i = j;
    } else if (lead >= 0xC0) {
      // a Greek letter (U+0370-U+03FF: lead byte 0xCE or 0xCF) followed by a lone 0: ω0
      const std::size_t n = utf8_length(lead);
      out += s.substr(i, n);
      i += n;
      const bool greek_letter = lead == 0xCE || lead == 0xCF;
      if (greek_letter && i < s.size() && s[i] == '0' &&
          (i + 1 == s.size() || !is_alnum(s[i + 1]))) {
        out += "_{0}";
        ++i;
      }
    } else if (c == '^' || c == '_') {
      std::string group = script_group(s, i);
      if (group.empty()) {
        out += std::string("\\") + c;
        ++i;
      } else {
        out += group;
      }
    } else if (c == '+' && i + 1 < s.size() && s[i + 1] == '-') {
      out += "±";
      i += 2;
    } else {
      if (c == '@' || c == '&' || c == '~' || c == '{' || c == '}' || c == '\\') out += '\\';
      out += c;
      ++i;
    }
  }
  return out;
}

std::string gnuplot_script(const Plot& plot, SvgSize size) {
  // The key sits below the axes, one entry a row when the labels are long: a plot of many
  // series grows by a key row's height (1.5 font sizes) for each series beyond the 4 that its
  // size leaves room for, so that the axes keep their height and the y label is not clipped.
  const int series = static_cast<int>(drawn_labels(plot).size());
  const int height = size.height + std::max(0, series - 4) * size.font * 3 / 2;
  std::ostringstream gp;
  gp << "set terminal svg size " << size.width << "," << height
     << " dynamic enhanced font 'DejaVu Sans," << size.font << "' background rgb 'white'\n"
     << "set encoding utf8\n";
  // Okabe-Ito colours (distinguishable with colour-blindness), no yellow on white
  const char* colours[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                           "#E69F00", "#56B4E9", "#000000", "#999999"};
  for (int i = 0; i < 8; ++i)
    gp << "set linetype " << i + 1 << " lc rgb '" << colours[i] << "' lw 2 pt 7 ps 0.5\n";
  gp << "set linetype cycle 8\n"
     << "set xlabel " << quoted(enhanced_text(plot.x_label)) << "\n"
     << "set ylabel " << quoted(enhanced_text(plot.y_label)) << "\n"
     << "set grid lc rgb '#dddddd'\n"
     << "set key below horizontal maxrows 4 height 1\n"  // half a line clear of the x label
     << "set border lw 1\n"
     << "set mxtics\nset mytics\n";
  if (plot.log_x) gp << "set logscale x 10\nset format x '%g'\n";
  if (plot.log_y) gp << "set logscale y 10\nset format y '%g'\n";
  if (plot.margins) gp << "set offsets 0, 0, graph 0.05, graph 0.05\n";
  // A series keeps the colour of its position in plot.series even when one before it has
  // nothing to draw, so that a figure family colours the same curve alike.
  std::vector<std::string> clauses;
  for (std::size_t i = 0; i < plot.series.size(); ++i) {
    const Series& s = plot.series[i];
    const std::string body = data_block(s, plot);
    if (body.empty()) continue;
    const std::string name = "$d" + std::to_string(i);
    gp << name << " << EOD\n" << body << "EOD\n";
    const char* columns = s.style == Series::Style::error_bars ? " using 1:2:3 " : " using 1:2 ";
    clauses.push_back(name + columns + style(s.style, static_cast<int>(i)) + " title " +
                      quoted(enhanced_text(s.label)));
  }
  if (clauses.empty())
    throw EmptyPlot("plot '" + plot.id + "' (" + plot.title + ") has no finite data to draw");
  gp << "plot ";
  for (std::size_t i = 0; i < clauses.size(); ++i) gp << (i ? ", \\\n     " : "") << clauses[i];
  gp << "\n";
  return gp.str();
}

std::string render_svg(const Plot& plot, const std::string& id_prefix, SvgSize size) {
  const std::string script = gnuplot_script(plot, size);
  TempDir dir;
  const fs::path script_file = dir.path / "plot.gp";
  {
    std::ofstream out(script_file);
    out << script;
    if (!out) throw std::runtime_error("cannot write the gnuplot script " + script_file.string());
  }
  const fs::path svg_file = dir.path / "plot.svg", err_file = dir.path / "stderr.txt";
  const int rc = run_process({IVV_GNUPLOT, script_file.string()}, svg_file, err_file);
  std::string svg = read_all(svg_file);
  if (rc != 0) {
    throw std::runtime_error("gnuplot (" + std::string(IVV_GNUPLOT) + ") failed on plot '" +
                             plot.id + "' with status " + std::to_string(rc) + ": " +
                             read_all(err_file));
  }
  const auto start = svg.find("<svg");
  if (start == std::string::npos)
    throw std::runtime_error("gnuplot produced no <svg> for plot '" + plot.id + "'");
  svg.erase(0, start);

  // Prefix every id, and every reference to one, so several plots can share a document.
  const std::string prefix = slug(id_prefix) + "-";
  std::vector<std::string> ids;
  for (const char* q : {"'", "\""}) {
    const std::string open = std::string(" id=") + q;
    for (std::size_t pos = svg.find(open); pos != std::string::npos;
         pos = svg.find(open, pos + 1)) {
      const std::size_t begin = pos + open.size(), end = svg.find(q, begin);
      if (end != std::string::npos) ids.push_back(svg.substr(begin, end - begin));
    }
  }
  for (const auto& id : ids) {
    for (const char* q : {"'", "\""}) {
      replace_all(svg, std::string(" id=") + q + id + q, std::string(" id=") + q + prefix + id + q);
      replace_all(svg, std::string(q) + "#" + id + q, std::string(q) + "#" + prefix + id + q);
    }
    replace_all(svg, "url(#" + id + ")", "url(#" + prefix + id + ")");
  }
  // Tooltips: the plot title and each series' plain label instead of what gnuplot puts there
  // (a generic name, or the label's enhanced-text markup).
  replace_all(svg, "<title>Gnuplot</title>", "<title>" + escape(plot.title) + "</title>");
  const auto labels = drawn_labels(plot);
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const std::string group = "gnuplot_plot_" + std::to_string(i + 1);
    for (const char* q : {"'", "\""}) {
      const auto at = svg.find(group + q);
      if (at == std::string::npos) continue;
      const auto open = svg.find("<title>", at), close = svg.find("</title>", at);
      if (open == std::string::npos || close == std::string::npos || open > at + 40) continue;
      svg.replace(open, close - open, "<title>" + escape(labels[i]));
    }
  }
  replace_all(svg, "<svg ",
              "<svg class=\"plot\" role=\"img\" aria-label=\"" + escape(plot.title) +
                  "\" data-plot-id=\"" + escape(plot.id) + "\" ");
  return svg;
}

SvgCheck check_svg(const std::string& svg) {
  SvgCheck check;
  check.has_svg = svg.find("<svg") != std::string::npos && svg.find("</svg>") != std::string::npos;
  // Each plotted series is a group <g id="...gnuplot_plot_N"> up to the next such group (the
  // last one up to the end). Its own key sample contributes one segment and one marker.
  const std::string marker = "gnuplot_plot_";
  std::vector<std::size_t> starts;
  for (std::size_t pos = svg.find(marker); pos != std::string::npos;
       pos = svg.find(marker, pos + 1)) {
    const std::size_t tag = svg.rfind('<', pos);
    if (tag != std::string::npos && svg.compare(tag, 3, "<g ") == 0 &&
        (starts.empty() || starts.back() != tag))
      starts.push_back(tag);
  }
  for (std::size_t i = 0; i < starts.size(); ++i) {
    const std::size_t end = i + 1 < starts.size() ? starts[i + 1] : svg.size();
    int segments = 0, markers = 0;
    for (std::size_t pos = svg.find("<path", starts[i]); pos < end;
         pos = svg.find("<path", pos + 1)) {
      std::size_t d = svg.find(" d=", pos);
      const std::size_t close = svg.find('>', pos);
      if (d == std::string::npos || d > close) continue;
      const char q = svg[d + 3];
      const std::size_t stop = svg.find(q, d + 4);
      for (std::size_t k = d + 4; k < stop; ++k)
        if (svg[k] == 'L' || svg[k] == 'l') ++segments;
    }
    for (std::size_t pos = svg.find("<use", starts[i]); pos < end; pos = svg.find("<use", pos + 1))
      ++markers;
    ++check.series;
    if (segments >= 2 || markers >= 2) ++check.drawn_series;
  }
  return check;
}

std::string gnuplot_version() {
  try {
    TempDir dir;
    const fs::path out = dir.path / "out.txt", err = dir.path / "err.txt";
    if (run_process({IVV_GNUPLOT, "--version"}, out, err) != 0) return "unavailable";
    std::string v = read_all(out);
    while (!v.empty() && (v.back() == '\n' || v.back() == '\r')) v.pop_back();
    return v.empty() ? "unavailable" : v;
  } catch (const std::exception&) {
    return "unavailable";
  }
}

}  // namespace ivv::reports
