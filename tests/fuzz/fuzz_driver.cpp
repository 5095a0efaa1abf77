// A fuzz driver of our own, built with the normal compiler and linked with one harness
// (fuzz_<reader>.cpp): replays the seed corpus, then runs deterministic seeded mutations of it
// (bit flips, byte and token inserts, erasures, splices, numbers replaced by extreme ones, deep
// nesting) for a bounded number of inputs and time. Registered in ctest as fuzz.<reader>.
//
//   fuzz_driver_<reader> CORPUS_DIR... [--iterations N] [--seconds S] [--seed K]
//                        [--max-input-seconds T] [--save-failures DIR]
//
// Exit 0 when every input was accepted or refused with an InputError. A failure (another
// exception, an input slower than T seconds) prints the seed and iteration that reproduce it,
// saves the input to DIR (default: the current folder) and exits 1; on a crash or abort (a
// fatal signal) the input is saved the same way before the process dies. Allocations are capped (address
// space 2 GiB unless built with a sanitizer), so an allocation sized by the file's numbers rather
// than its data shows up as std::bad_alloc.
#include <fcntl.h>
#include <sys/resource.h>
#include <unistd.h>

#include <csignal>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <random>
#include <sstream>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

namespace fs = std::filesystem;
using Bytes = std::string;
using Clock = std::chrono::steady_clock;

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif
#else
constexpr bool kSanitized = false;
#endif

constexpr std::size_t kMaxInput = 1 << 16;

/// Tokens a reader may trip on: numbers at and beyond the range of double and int, separators.
const std::vector<std::string> kNumbers = {
    "1e308", "1.7976931348623157e308", "1e309", "1e400", "-1e400", "-0", "-0.0", "0", "nan",
    "-nan", "inf", "-inf", "Infinity", "NaN", "4.9e-324", "2.4e-324", "1e-320", "-1e-400", "1",
    "-1", "2", "3", "65", "1000000", "2147483647", "2147483648", "-2147483649", "4294967295",
    "4294967297", "9223372036854775807", "9223372036854775808", "-9223372036854775808",
    "18446744073709551616", "99999999999999999999999", "10000000", "10000001", "0x10", "1e",
    ".", "+", "-", "1.5", "0.5e-3"};
const std::vector<std::string> kTokens = {
    " ", "\n", "\t", "\r\n", "[", "]", "{", "}", ",", ":", "\"", "\"M\"", "\"q\"", "\"M_mtx\"",
    "\"name\"", "null", "true", "%", "%%MatrixMarket matrix coordinate real general\n",
    "%%MatrixMarket matrix array real symmetric\n", "symmetric", "general", "array",
    "coordinate", "\xff", "\xc3\xa9", std::string(1, '\0'), "\\u0000", "\\ud800"};

/// A deterministic random source: mt19937_64's output is fixed by the standard (the standard
/// distributions are not, so they are not used).
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : g_(seed) {}
  std::size_t below(std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(g_() % n); }
  template <class T>
  const T& pick(const std::vector<T>& v) { return v[below(v.size())]; }

 private:
  std::mt19937_64 g_;
};

bool is_number_char(char c) {
  return (c >= '0' && c <= '9') || c == '.' || c == 'e' || c == 'E' || c == '+' || c == '-';
}

/// One mutation of `in`, chosen at random; `corpus` feeds splices.
void mutate(Bytes& s, const std::vector<Bytes>& corpus, Rng& rng) {
  const std::size_t pos = rng.below(s.size() + 1);
  switch (rng.below(9)) {
    case 0:  // flip one bit
      if (!s.empty()) s[pos % s.size()] = static_cast<char>(s[pos % s.size()] ^ (1 << rng.below(8)));
      break;
    case 1:  // overwrite a byte
      if (!s.empty()) s[pos % s.size()] = static_cast<char>(rng.below(256));
      break;
    case 2:  // insert a token
      s.insert(pos, rng.pick(kTokens));
      break;
    case 3:  // erase a range
      if (!s.empty()) s.erase(pos % s.size(), 1 + rng.below(std::min<std::size_t>(s.size(), 32)));
      break;
    case 4: {  // duplicate a range in place
      if (s.empty()) break;
      const std::size_t a = pos % s.size(), len = 1 + rng.below(std::min<std::size_t>(s.size() - a, 64));
      s.insert(a, s.substr(a, len));
      break;
    }
    case 5: {  // splice: a prefix of this input, a suffix of another
      const Bytes& other = rng.pick(corpus);
      s = s.substr(0, pos) + other.substr(rng.below(other.size() + 1));
      break;
    }
    case 6:
    case 7: {  // replace a number (a run of number characters) by an extreme one
      std::vector<std::size_t> starts;
      for (std::size_t k = 0; k < s.size(); ++k)
        if (is_number_char(s[k]) && (k == 0 || !is_number_char(s[k - 1]))) starts.push_back(k);
      if (starts.empty()) {
        s.insert(pos, rng.pick(kNumbers));
        break;
      }
      const std::size_t a = rng.pick(starts);
      std::size_t b = a;
      while (b < s.size() && is_number_char(s[b])) ++b;
      s.replace(a, b - a, rng.pick(kNumbers));
      break;
    }
    case 8: {  // deep nesting or a long run
      const char c = "[{(%\n 9"[rng.below(7)];
      s.insert(pos, std::string(1 + rng.below(20000), c));
      break;
    }
  }
  if (s.size() > kMaxInput) s.resize(kMaxInput);
}

std::string preview(const Bytes& s) {
  std::ostringstream out;
  for (std::size_t k = 0; k < std::min<std::size_t>(s.size(), 160); ++k) {
    const auto c = static_cast<unsigned char>(s[k]);
    if (c == '\n') out << "\\n";
    else if (c >= 32 && c < 127 && c != '\\') out << s[k];
    else out << "\\x" << std::hex << static_cast<int>(c) << std::dec;
  }
  if (s.size() > 160) out << "...";
  return out.str();
}

struct Options {
  std::vector<fs::path> corpus_dirs;
  std::uint64_t iterations = 10000;
  double seconds = 10;
  std::uint64_t seed = 1;
  double max_input_seconds = 2;
  fs::path save_dir = ".";
};

Options parse_options(int argc, char** argv) {
  Options o;
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    auto value = [&]() -> std::string {
      if (k + 1 >= argc) throw std::invalid_argument(a + " needs a value");
      return argv[++k];
    };
    if (a == "--iterations") o.iterations = std::stoull(value());
    else if (a == "--seconds") o.seconds = std::stod(value());
    else if (a == "--seed") o.seed = std::stoull(value());
    else if (a == "--max-input-seconds") o.max_input_seconds = std::stod(value());
    else if (a == "--save-failures") o.save_dir = value();
    else o.corpus_dirs.emplace_back(a);
  }
  if (o.corpus_dirs.empty()) throw std::invalid_argument("no corpus folder given");
  return o;
}

std::vector<Bytes> load_corpus(const std::vector<fs::path>& dirs) {
  std::vector<fs::path> files;
  for (const auto& d : dirs)
    for (const auto& e : fs::recursive_directory_iterator(d))
      if (e.is_regular_file()) files.push_back(e.path());
  std::sort(files.begin(), files.end());  // a fixed order: the run is reproducible
  std::vector<Bytes> corpus;
  for (const auto& f : files) {
    std::ifstream in(f, std::ios::binary);
    corpus.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  return corpus;
}

// The input being run, for the fatal-signal handler (which may only make async-signal-safe calls).
const Bytes* g_current = nullptr;
char g_crash_path[4096] = {0};

extern "C" void on_fatal_signal(int sig) {
  if (g_current != nullptr) {
    const int fd = ::open(g_crash_path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      ssize_t ignored = ::write(fd, g_current->data(), g_current->size());
      (void)ignored;
      ::close(fd);
    }
    const char msg[] = "\nfuzz driver: fatal signal; the input is saved to ";
    ssize_t ignored = ::write(2, msg, sizeof msg - 1);
    ignored = ::write(2, g_crash_path, std::strlen(g_crash_path));
    ignored = ::write(2, "\n", 1);
    (void)ignored;
  }
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

/// Runs one input; false (after saving it) on a finding other than a crash.
bool run_one(const Bytes& input, const std::string& label, const Options& o) {
  const std::string crash_path = (o.save_dir / ("fuzz-crash-" + label + ".bin")).string();
  std::snprintf(g_crash_path, sizeof g_crash_path, "%s", crash_path.c_str());
  g_current = &input;
  const auto start = Clock::now();
  std::string failure;
  try {
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(input.data()), input.size());
  } catch (const std::exception& e) {
    failure = std::string("unexpected exception: ") + e.what();
  } catch (...) {
    failure = "unexpected non-standard exception";
  }
  g_current = nullptr;
  const double took = std::chrono::duration<double>(Clock::now() - start).count();
  if (failure.empty() && took > o.max_input_seconds)
    failure = "took " + std::to_string(took) + " s (limit " + std::to_string(o.max_input_seconds) + " s)";
  if (failure.empty()) return true;
  const fs::path saved = o.save_dir / ("fuzz-failure-" + label + ".bin");
  std::ofstream(saved, std::ios::binary) << input;
  std::cerr << "FAILURE on " << label << ": " << failure << "\n  input (" << input.size()
            << " bytes, saved to " << saved.string() << "): " << preview(input) << '\n';
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  try {
    o = parse_options(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "fuzz driver: " << e.what()
              << "\nusage: " << argv[0]
              << " CORPUS_DIR... [--iterations N] [--seconds S] [--seed K] [--max-input-seconds T]"
                 " [--save-failures DIR]\n";
    return 2;
  }
  for (int sig : {SIGSEGV, SIGABRT, SIGBUS, SIGFPE, SIGILL}) std::signal(sig, on_fatal_signal);
  if (!kSanitized) {  // an allocation sized by a number, not by data, fails loudly
    const rlimit cap{rlim_t{2} << 30, rlim_t{2} << 30};
    setrlimit(RLIMIT_AS, &cap);
  }
  const std::vector<Bytes> corpus = load_corpus(o.corpus_dirs);
  if (corpus.empty()) {
    std::cerr << "fuzz driver: the corpus is empty\n";
    return 2;
  }
  const auto start = Clock::now();
  bool ok = true;
  for (std::size_t k = 0; k < corpus.size(); ++k) ok &= run_one(corpus[k], "corpus-" + std::to_string(k), o);
  Rng rng(o.seed);
  std::uint64_t done = 0;
  for (; done < o.iterations; ++done) {
    if (std::chrono::duration<double>(Clock::now() - start).count() > o.seconds) break;
    Bytes input = rng.pick(corpus);
    const std::size_t rounds = 1 + rng.below(4);
    for (std::size_t r = 0; r < rounds; ++r) mutate(input, corpus, rng);
    ok &= run_one(input, "seed-" + std::to_string(o.seed) + "-iteration-" + std::to_string(done), o);
  }
  const double took = std::chrono::duration<double>(Clock::now() - start).count();
  std::cout << "fuzz driver: " << corpus.size() << " corpus inputs and " << done
            << " mutations (seed " << o.seed << ") in " << took << " s: "
            << (ok ? "no failure" : "FAILURES (see above)") << '\n';
  if (done < o.iterations)
    std::cout << "  stopped by the time limit of " << o.seconds << " s before " << o.iterations
              << " mutations\n";
  return ok ? 0 : 1;
}
