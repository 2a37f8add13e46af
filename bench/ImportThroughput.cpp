// bench: import of a large samples.csv (docs/benchmarks.md: ≥ 1.5 million
// samples/s, peak memory ≤ 1.5 × the CSV). The import runs as a user runs it,
// `driftlab-cli import` in a child process, so that its peak memory is its own
// (wait4's ru_maxrss), not the benchmark's.
#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <vector>

#include "bench/BenchFigures.h"
#include "core/bundle/CampaignJson.h"

extern char** environ;

namespace driftlab::bench {
namespace {

/// Eight temperatures plus the axis columns, one moving run: the shape of a
/// long logged warm-up.
Campaign benchCampaign() {
    Campaign c;
    c.name = QStringLiteral("import benchmark");
    c.machine.name = QStringLiteral("bench");
    c.machine.axis = QStringLiteral("X");
    c.screw = Screw{};
    c.screw->length_mm = 900;
    c.screw->diameter_mm = 40;
    c.screw->lead_mm = 10;
    c.screw->fixed_end_mm = -40;
    c.screw->mounting = QStringLiteral("fixed-free");
    c.screw->alpha_per_K = 11.5e-6;
    c.screw->density_kg_m3 = 7850;
    c.screw->specific_heat_J_kgK = 460;
    c.screw->conductivity_W_mK = 45;
    c.nut_length_mm = 80;
    c.travel_mm = RangeMm{0, 700};
    for (int k = 0; k < 8; ++k)
        c.channels.push_back({QStringLiteral("T_%1").arg(k),
                              Quantity::Temperature,
                              k == 0 ? ChannelRole::Nut : ChannelRole::Other,
                              {},
                              {},
                              {}});
    Run run;
    run.id = QStringLiteral("S1");
    c.runs.push_back(run);
    return c;
}

void append(std::string& out, double value, int decimals) {
    char buffer[32];
    auto [end, ec] =
        std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, decimals);
    out.append(buffer, end);
}

/// Writes the bundle with a samples.csv of about `megabytes` MB; returns the sample count.
qint64 writeBenchBundle(const QString& dir, int megabytes) {
    QDir().mkpath(dir);
    const Campaign c = benchCampaign();
    QFile json(QDir(dir).filePath(QStringLiteral("campaign.json")));
    json.open(QIODevice::WriteOnly);
    json.write(QJsonDocument(bundle::campaignToJson(c)).toJson());
    QFile csv(QDir(dir).filePath(QStringLiteral("samples.csv")));
    if (!csv.open(QIODevice::WriteOnly)) throw CliError(QStringLiteral("cannot write ") + dir);
    std::string out = "run,time_s";
    for (const Channel& ch : c.channels) out += ',' + ch.id.toStdString();
    out += ",position_mm,feed_mm_min,torque_Nm\n";
    const qint64 target = qint64(megabytes) << 20;
    qint64 written = 0, rows = 0;
    std::uint32_t noise = 12345;
    while (written < target) {
        out += "S1,";
        append(out, 0.1 * double(rows), 1);
        for (std::size_t k = 0; k < c.channels.size(); ++k) {
            noise = noise * 1664525u + 1013904223u;  // deterministic, cheap
            out += ',';
            append(out, 20.0 + 5.0 * double(rows) / 1e7 + double(noise >> 20) * 1e-6, 4);
        }
        out += ',';
        append(out, 350.0 + 340.0 * std::sin(double(rows) * 1e-3), 3);
        out += ",8000.0,1.250\n";
        ++rows;
        if (out.size() > (1u << 20)) {
            written += csv.write(out.data(), qint64(out.size()));
            out.clear();
        }
    }
    written += csv.write(out.data(), qint64(out.size()));
    return rows * qint64(c.channels.size() + 3);
}

struct ChildRun {
    int exitCode = -1;
    double seconds = 0;
    double peakRss_mb = 0;
};

/// Runs this executable with `args`, stdout and stderr to /dev/null.
ChildRun runSelf(const QStringList& args) {
    const QByteArray program = cliExecutable().toLocal8Bit();
    std::vector<QByteArray> storage{program};
    for (const QString& a : args) storage.push_back(a.toLocal8Bit());
    std::vector<char*> argv;
    for (QByteArray& a : storage) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    ChildRun run;
    QElapsedTimer timer;
    timer.start();
    pid_t pid = 0;
    const int spawned =
        posix_spawn(&pid, program.constData(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0) return run;
    int status = 0;
    rusage usage{};
    if (wait4(pid, &status, 0, &usage) != pid) return run;
    run.seconds = timer.nsecsElapsed() * 1e-9;
    run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    run.peakRss_mb = double(usage.ru_maxrss) / 1024.0;  // Linux: kB
    return run;
}

}  // namespace

QJsonObject importFigures(int megabytes, int repetitions) {
    QTemporaryDir dir;
    const QString bundle = dir.filePath(QStringLiteral("bundle"));
    printProgress(QStringLiteral("import: writing a %1 MB samples.csv").arg(megabytes), 0);
    const qint64 samples = writeBenchBundle(bundle, megabytes);
    const double csv_mb =
        double(QFileInfo(QDir(bundle).filePath(QStringLiteral("samples.csv"))).size()) / (1 << 20);
    printProgress(QStringLiteral("import: writing a %1 MB samples.csv").arg(megabytes), 1);
    std::vector<double> rates, peaks;
    for (int i = 0; i < repetitions; ++i) {
        const ChildRun run = runSelf({QStringLiteral("import"), bundle, QStringLiteral("--db"),
                                      dir.filePath(QStringLiteral("lab%1.sqlite").arg(i))});
        if (run.exitCode != 0)
            throw CliError(
                QStringLiteral("the benchmark's import failed (exit %1)").arg(run.exitCode));
        rates.push_back(double(samples) / run.seconds);
        peaks.push_back(run.peakRss_mb);
        printProgress(QStringLiteral("import"), (i + 1.0) / repetitions);
    }
    return {{QStringLiteral("import_csv_mb"), csv_mb},
            {QStringLiteral("import_samples"), samples},
            {QStringLiteral("import_samples_per_s"), median(rates)},
            {QStringLiteral("import_peak_rss_mb"), median(peaks)},
            {QStringLiteral("import_peak_memory_ratio"), median(peaks) / csv_mb}};
}

}  // namespace driftlab::bench
