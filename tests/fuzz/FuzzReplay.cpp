// The main() of a fuzz target in the product (GCC) build, which has no libFuzzer:
// every seed file goes through LLVMFuzzerTestOneInput as it is, then a fixed
// number of mutations of it (byte flips, inserts, deletions, truncations,
// splices of two seeds, repeated chunks). The generator has a fixed seed, so a
// run is the same on every machine and a failure reproduces; it is written out
// by hand (not <random>'s distributions, whose results the standard leaves to
// the library) for that reason.
//
//   <target> [--mutations N] [--seed S] [--max-size BYTES] [--timeout SECONDS]
//            [--artifacts DIR] FILE|DIR...
//
// Silent on success. A crash (signal), an exception that escapes the target or
// an input that takes longer than the timeout prints the input, saves it to
// DIR/<target>-failed-input and exits non-zero; `<target> --mutations 0 FILE`
// replays a saved input, and the libFuzzer build runs the same file.
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);
// Optional, as in libFuzzer: a target without it leaves the symbol null.
extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) __attribute__((weak));

using namespace std::string_view_literals;

namespace {

using Bytes = std::vector<std::uint8_t>;

struct Seed {
    std::string path;
    Bytes bytes;
};

// What the signal handler needs, prepared beforehand (it may only make
// async-signal-safe calls: no allocation, no stdio).
std::string g_artifactDir;
std::string g_artifactPath;
std::string g_target;   // for messages: the executable's name
std::string g_command;  // to rerun it: argv[0]
const Bytes* g_input = nullptr;
const char* g_seedPath = "";
long g_mutation = -1;  // -1: the seed itself
unsigned g_timeout = 0;

void say(const char* text) {
    const std::size_t n = std::strlen(text);
    std::size_t done = 0;
    while (done < n) {
        const ssize_t w = ::write(STDERR_FILENO, text + done, n - done);
        if (w <= 0) return;
        done += std::size_t(w);
    }
}

void sayNumber(unsigned long value) {
    char digits[24];
    int i = sizeof digits - 1;
    digits[i] = '\0';
    do {
        digits[--i] = char('0' + value % 10);
        value /= 10;
    } while (value != 0 && i > 0);
    say(digits + i);
}

/// Saves the current input to g_artifactPath with system calls only.
bool saveInput() {
    if (!g_input) return false;
    ::mkdir(g_artifactDir.c_str(), 0777);  // may exist already
    const int fd = ::open(g_artifactPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0666);
    if (fd < 0) return false;
    std::size_t done = 0;
    while (done < g_input->size()) {
        const ssize_t w = ::write(fd, g_input->data() + done, g_input->size() - done);
        if (w <= 0) break;
        done += std::size_t(w);
    }
    ::close(fd);
    return done == g_input->size();
}

/// The failing input, escaped, its first bytes; where it is saved; how to rerun it.
void reportFailure(const char* what) {
    say(g_target.c_str());
    say(": ");
    say(what);
    say("\n  on ");
    if (g_mutation < 0) {
        say("seed ");
        say(g_seedPath);
    } else {
        say("mutation ");
        sayNumber(static_cast<unsigned long>(g_mutation));
        say(" of seed ");
        say(g_seedPath);
    }
    if (!g_input) {
        say("\n");
        return;
    }
    say(" (");
    sayNumber(g_input->size());
    say(" bytes):\n  \"");
    constexpr std::size_t kShown = 512;
    char escaped[8];
    for (std::size_t i = 0; i < g_input->size() && i < kShown; ++i) {
        const unsigned c = (*g_input)[i];
        if (c == '\\' || c == '"') {
            escaped[0] = '\\';
            escaped[1] = char(c);
            escaped[2] = '\0';
        } else if (c >= 0x20 && c < 0x7f) {
            escaped[0] = char(c);
            escaped[1] = '\0';
        } else {
            static const char hex[] = "0123456789abcdef";
            escaped[0] = '\\';
            escaped[1] = 'x';
            escaped[2] = hex[c >> 4];
            escaped[3] = hex[c & 15];
            escaped[4] = '\0';
        }
        say(escaped);
    }
    say(g_input->size() > kShown ? "\"...\n" : "\"\n");
    if (saveInput()) {
        say("  saved to ");
        say(g_artifactPath.c_str());
        say("; rerun: ");
        say(g_command.c_str());
        say(" --mutations 0 ");
        say(g_artifactPath.c_str());
        say("\n");
    } else {
        say("  (could not save it to ");
        say(g_artifactPath.c_str());
        say(")\n");
    }
}

extern "C" void onSignal(int signal) {
    if (signal == SIGALRM) {
        say("\n");
        reportFailure("the input took longer than the timeout");
        std::_Exit(3);
    }
    say("\n");
    reportFailure(signal == SIGSEGV  ? "crashed (SIGSEGV)"
                  : signal == SIGBUS ? "crashed (SIGBUS)"
                  : signal == SIGFPE ? "crashed (SIGFPE)"
                  : signal == SIGILL ? "crashed (SIGILL)"
                                     : "aborted (SIGABRT)");
    // Die of the same signal, so the exit status says what happened.
    ::signal(signal, SIG_DFL);
    ::raise(signal);
}

void installHandlers() {
    // Its own stack, so a stack overflow is reported too.
    static std::array<char, 1 << 16> stack;
    stack_t alternate{};
    alternate.ss_sp = stack.data();
    alternate.ss_size = stack.size();
    ::sigaltstack(&alternate, nullptr);
    struct sigaction action {};
    action.sa_handler = onSignal;
    action.sa_flags = SA_ONSTACK;
    sigemptyset(&action.sa_mask);
    for (int signal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGALRM})
        ::sigaction(signal, &action, nullptr);
}

/// splitmix64: small, fast and the same everywhere.
class Random {
public:
    explicit Random(std::uint64_t seed) : m_state(seed) {}
    std::uint64_t next() {
        std::uint64_t z = (m_state += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    /// In [0, n); n > 0.
    std::size_t below(std::size_t n) { return std::size_t(next() % n); }

private:
    std::uint64_t m_state;
};

// The bytes and tokens that matter to CSV and JSON readers: separators, quotes,
// line ends, numbers at the edge of their type.
constexpr std::string_view kBytes = ",;\t\"\n\r\0{}[]:.-+eE0123456789 \\x"sv;
constexpr std::array<std::string_view, 22> kTokens = {
    "NaN",  "inf",  "-0",   "1e308", "1e-320", "-1e309",    "4294967296", "9223372036854775808",
    "\"\"", "null", "true", "[]",    "{}",     "0x",        "0xFFFFFFFF", "\r\n",
    ",,",   ";",    "\"\n", "1,5",   "-",      "2147483648"};

Bytes mutate(const Bytes& seed, const std::vector<Seed>& all, Random& random, std::size_t maxSize) {
    Bytes out = seed;
    const std::size_t steps = 1 + random.below(4);
    for (std::size_t step = 0; step < steps; ++step) {
        switch (random.below(8)) {
            case 0:  // flip one bit
                if (!out.empty())
                    out[random.below(out.size())] ^= std::uint8_t(1u << random.below(8));
                break;
            case 1:  // overwrite a byte
                if (!out.empty())
                    out[random.below(out.size())] =
                        random.below(2) ? std::uint8_t(random.next())
                                        : std::uint8_t(kBytes[random.below(kBytes.size())]);
                break;
            case 2: {  // insert a few bytes
                const std::size_t at = random.below(out.size() + 1);
                const std::size_t n = 1 + random.below(8);
                for (std::size_t i = 0; i < n; ++i)
                    out.insert(out.begin() + std::ptrdiff_t(at),
                               std::uint8_t(kBytes[random.below(kBytes.size())]));
                break;
            }
            case 3: {  // insert a token
                const std::string_view token = kTokens[random.below(kTokens.size())];
                out.insert(out.begin() + std::ptrdiff_t(random.below(out.size() + 1)),
                           token.begin(), token.end());
                break;
            }
            case 4:  // delete a range
                if (!out.empty()) {
                    const std::size_t at = random.below(out.size());
                    const std::size_t n =
                        1 + random.below(std::min<std::size_t>(out.size() - at, 64));
                    out.erase(out.begin() + std::ptrdiff_t(at),
                              out.begin() + std::ptrdiff_t(at + n));
                }
                break;
            case 5:  // truncate
                out.resize(random.below(out.size() + 1));
                break;
            case 6: {  // splice: this input's head, another seed's tail
                const Bytes& other = all[random.below(all.size())].bytes;
                const std::size_t head = random.below(out.size() + 1);
                const std::size_t tail = random.below(other.size() + 1);
                out.resize(head);
                out.insert(out.end(), other.begin() + std::ptrdiff_t(tail), other.end());
                break;
            }
            case 7:  // repeat a chunk: long lines, many columns, deep nesting
                if (!out.empty()) {
                    const std::size_t at = random.below(out.size());
                    const std::size_t n =
                        1 + random.below(std::min<std::size_t>(out.size() - at, 32));
                    const Bytes chunk(out.begin() + std::ptrdiff_t(at),
                                      out.begin() + std::ptrdiff_t(at + n));
                    const std::size_t times = 1 + random.below(std::size_t(1) << random.below(10));
                    for (std::size_t i = 0; i < times && out.size() + n <= maxSize; ++i)
                        out.insert(out.begin() + std::ptrdiff_t(at), chunk.begin(), chunk.end());
                }
                break;
        }
        if (out.size() > maxSize) out.resize(maxSize);
    }
    return out;
}

bool readFile(const std::filesystem::path& path, Bytes& bytes) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return !in.bad();
}

/// The files named, a folder's files in name order (so the order, and with it
/// every mutation, is the same on every machine).
bool collectSeeds(const std::string& argument, std::vector<Seed>& seeds) {
    std::error_code error;
    std::vector<std::filesystem::path> paths;
    if (std::filesystem::is_directory(argument, error)) {
        for (const auto& entry : std::filesystem::directory_iterator(argument, error))
            if (entry.is_regular_file()) paths.push_back(entry.path());
        std::sort(paths.begin(), paths.end());
    } else {
        paths.emplace_back(argument);
    }
    for (const auto& path : paths) {
        Seed seed{path.string(), {}};
        if (!readFile(path, seed.bytes)) {
            std::fprintf(stderr, "%s: cannot read %s\n", g_target.c_str(), seed.path.c_str());
            return false;
        }
        seeds.push_back(std::move(seed));
    }
    return true;
}

void runOne(const Bytes& input) {
    g_input = &input;
    if (g_timeout) ::alarm(g_timeout);
    try {
        // libFuzzer never passes null, even for an empty input.
        static const std::uint8_t empty = 0;
        (void)LLVMFuzzerTestOneInput(input.empty() ? &empty : input.data(), input.size());
    } catch (const std::exception& e) {
        const std::string what = std::string("an exception escaped the target: ") + e.what();
        reportFailure(what.c_str());
        std::exit(1);
    } catch (...) {
        reportFailure("an exception of unknown type escaped the target");
        std::exit(1);
    }
    if (g_timeout) ::alarm(0);
}

int usage() {
    std::fprintf(stderr,
                 "usage: %s [--mutations N] [--seed S] [--max-size BYTES] [--timeout SECONDS] "
                 "[--artifacts DIR] FILE|DIR...\n",
                 g_target.c_str());
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    g_command = argv[0];
    g_target = std::filesystem::path(g_command).filename().string();
    long mutations = 100;
    std::uint64_t seedValue = 1;
    unsigned long maxSize = 1 << 20;
    g_timeout = 10;
    g_artifactDir = ".";
    std::vector<Seed> seeds;
    for (int i = 1; i < argc; ++i) {
        const std::string_view arg = argv[i];
        const bool hasValue = i + 1 < argc;
        char* end = nullptr;
        if (arg == "--mutations" && hasValue)
            mutations = std::strtol(argv[++i], &end, 10);
        else if (arg == "--seed" && hasValue)
            seedValue = std::strtoull(argv[++i], &end, 10);
        else if (arg == "--max-size" && hasValue)
            maxSize = std::strtoul(argv[++i], &end, 10);
        else if (arg == "--timeout" && hasValue)
            g_timeout = unsigned(std::strtoul(argv[++i], &end, 10));
        else if (arg == "--artifacts" && hasValue)
            g_artifactDir = argv[++i];
        else if (arg.starts_with("--"))
            return usage();
        else if (!collectSeeds(argv[i], seeds))
            return 2;
        if (end && *end != '\0') return usage();
    }
    if (seeds.empty() || mutations < 0 || maxSize == 0) return usage();
    g_artifactPath = g_artifactDir + "/" + g_target + "-failed-input";

    installHandlers();
    if (LLVMFuzzerInitialize) LLVMFuzzerInitialize(&argc, &argv);
    for (const Seed& seed : seeds) {
        g_seedPath = seed.path.c_str();
        g_mutation = -1;
        runOne(seed.bytes);
    }
    Random random(seedValue);
    for (const Seed& seed : seeds) {
        g_seedPath = seed.path.c_str();
        for (long m = 0; m < mutations; ++m) {
            g_mutation = m;
            const Bytes input = mutate(seed.bytes, seeds, random, maxSize);
            runOne(input);
        }
    }
    return 0;
}
