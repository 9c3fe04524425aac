// Workload generator for `make bench` and the large end-to-end checks. Writes Triangle-format
// files; deterministic for a given kind, size and seed.
//
//   deltri_bench_gen uniform|gaussian|grid|clustered|collinear N out.node
//   deltri_bench_gen holes K out.poly        unit square with KxK circular holes of 64 segments
//   deltri_bench_gen square out.poly         the unit square
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

namespace {

struct Writer {
  std::FILE* f;
  char buf[64];
  void num(double v) {
    auto r = std::to_chars(buf, buf + sizeof buf, v);
    std::fwrite(buf, 1, static_cast<std::size_t>(r.ptr - buf), f);
  }
  void num(long v) {
    auto r = std::to_chars(buf, buf + sizeof buf, v);
    std::fwrite(buf, 1, static_cast<std::size_t>(r.ptr - buf), f);
  }
  void text(const char* s) { std::fputs(s, f); }
};

using Points = std::vector<std::pair<double, double>>;

Points make_points(const std::string& kind, long n) {
  std::mt19937_64 rng(20261122);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> g(0.0, 1.0);
  Points p;
  p.reserve(static_cast<std::size_t>(n));
  if (kind == "uniform") {
    for (long i = 0; i < n; ++i) p.emplace_back(u(rng), u(rng));
  } else if (kind == "gaussian") {
    for (long i = 0; i < n; ++i) p.emplace_back(g(rng), g(rng));
  } else if (kind == "grid") {
    const long side = static_cast<long>(std::llround(std::sqrt(static_cast<double>(n))));
    for (long i = 0; i < side; ++i)
      for (long j = 0; j < side; ++j) p.emplace_back(static_cast<double>(i), static_cast<double>(j));
  } else if (kind == "clustered") {
    const long clusters = 100;
    std::vector<std::pair<double, double>> centre;
    for (long c = 0; c < clusters; ++c) centre.emplace_back(u(rng), u(rng));
    for (long i = 0; i < n; ++i) {
      const auto& c = centre[static_cast<std::size_t>(i % clusters)];
      p.emplace_back(c.first + 1e-3 * g(rng), c.second + 1e-3 * g(rng));
    }
  } else if (kind == "collinear") {
    for (long i = 0; i < n; ++i) p.emplace_back(0.5 * static_cast<double>(i), 2.0 + 0.25 * static_cast<double>(i));
  } else {
    std::fprintf(stderr, "unknown kind %s\n", kind.c_str());
    std::exit(2);
  }
  return p;
}

void write_node(const Points& p, const char* path) {
  Writer w{std::fopen(path, "wb"), {}};
  if (!w.f) { std::perror(path); std::exit(1); }
  w.num(static_cast<long>(p.size()));
  w.text(" 2 0 0\n");
  for (std::size_t i = 0; i < p.size(); ++i) {
    w.num(static_cast<long>(i + 1)); w.text(" "); w.num(p[i].first); w.text(" "); w.num(p[i].second); w.text("\n");
  }
  std::fclose(w.f);
}

// Unit square with k x k holes, each a circle of 64 segments; 4 + 64 k^2 vertices and segments.
void write_holes(long k, const char* path) {
  Writer w{std::fopen(path, "wb"), {}};
  if (!w.f) { std::perror(path); std::exit(1); }
  const long per = 64, nv = 4 + per * k * k;
  const double cell = 1.0 / static_cast<double>(k), radius = 0.3 * cell;
  w.num(nv); w.text(" 2 0 0\n");
  const double corner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  long id = 1;
  for (auto& c : corner) { w.num(id++); w.text(" "); w.num(c[0]); w.text(" "); w.num(c[1]); w.text("\n"); }
  for (long i = 0; i < k; ++i)
    for (long j = 0; j < k; ++j)
      for (long s = 0; s < per; ++s) {
        const double a = 2.0 * M_PI * static_cast<double>(s) / static_cast<double>(per);
        w.num(id++); w.text(" ");
        w.num((static_cast<double>(i) + 0.5) * cell + radius * std::cos(a)); w.text(" ");
        w.num((static_cast<double>(j) + 0.5) * cell + radius * std::sin(a)); w.text("\n");
      }
  w.num(nv); w.text(" 0\n");
  long sid = 1;
  for (long c = 0; c < 4; ++c) { w.num(sid++); w.text(" "); w.num(c + 1); w.text(" "); w.num((c + 1) % 4 + 1); w.text("\n"); }
  for (long h = 0; h < k * k; ++h)
    for (long s = 0; s < per; ++s) {
      const long base = 5 + h * per;
      w.num(sid++); w.text(" "); w.num(base + s); w.text(" "); w.num(base + (s + 1) % per); w.text("\n");
    }
  w.num(k * k); w.text("\n");
  long hid = 1;
  for (long i = 0; i < k; ++i)
    for (long j = 0; j < k; ++j) {
      w.num(hid++); w.text(" ");
      w.num((static_cast<double>(i) + 0.5) * cell); w.text(" ");
      w.num((static_cast<double>(j) + 0.5) * cell); w.text("\n");
    }
  std::fclose(w.f);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 4 && std::string(argv[1]) == "holes") {
    write_holes(std::atol(argv[2]), argv[3]);
  } else if (argc == 3 && std::string(argv[1]) == "square") {
    std::FILE* f = std::fopen(argv[2], "wb");
    if (!f) return 1;
    std::fputs("4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n", f);
    std::fclose(f);
  } else if (argc == 4) {
    write_node(make_points(argv[1], std::atol(argv[2])), argv[3]);
  } else {
    std::fprintf(stderr, "usage: deltri_bench_gen KIND N out.node | holes K out.poly | square out.poly\n");
    return 2;
  }
  return 0;
}
