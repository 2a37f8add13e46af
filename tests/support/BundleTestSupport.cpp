#include "tests/support/BundleTestSupport.h"

#include <gtest/gtest.h>
#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <random>

#include "core/bundle/BundleReader.h"

namespace driftlab::test {

QString exampleBundlePath() {
    return QStringLiteral(DRIFTLAB_SOURCE_DIR "/resources/examples/x-axis-moving-state");
}

Campaign exampleCampaign() {
    bundle::BundleReadResult r = bundle::readBundle(exampleBundlePath());
    EXPECT_TRUE(r.ok());
    return *r.campaign;
}

void copyBundle(const QString& from, const QString& target) {
    QDir().mkpath(target);
    for (const QString& name : QDir(from).entryList(QDir::Files))
        ASSERT_TRUE(QFile::copy(QDir(from).filePath(name), QDir(target).filePath(name)))
            << qPrintable(name);
}

QByteArray readFile(const QString& path) {
    QFile f(path);
    EXPECT_TRUE(f.open(QIODevice::ReadOnly)) << qPrintable(path);
    return f.readAll();
}

void writeFile(const QString& path, const QByteArray& content) {
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly | QIODevice::Truncate)) << qPrintable(path);
    f.write(content);
}

void replaceInFile(const QString& path, const QByteArray& what, const QByteArray& with) {
    QByteArray content = readFile(path);
    const qsizetype at = content.indexOf(what);
    ASSERT_GE(at, 0) << "'" << what.constData() << "' not in " << qPrintable(path);
    content.replace(at, what.size(), with);
    writeFile(path, content);
}

void rewriteColumn(const QString& path, int column, const std::function<QByteArray(double)>& f,
                   const QByteArray& run) {
    QList<QByteArray> lines = readFile(path).split('\n');
    for (qsizetype i = 1; i < lines.size(); ++i) {
        QList<QByteArray> cells = lines[i].split(',');
        if (cells.size() <= column || cells[column].isEmpty()) continue;
        if (!run.isEmpty() && cells[0] != run) continue;
        cells[column] = f(cells[column].toDouble());
        lines[i] = cells.join(',');
    }
    writeFile(path, lines.join('\n'));
}

QByteArray sha256OfFile(const QString& path) {
    return QCryptographicHash::hash(readFile(path), QCryptographicHash::Sha256).toHex();
}

Campaign generatedCampaign(std::size_t rows, unsigned seed) {
    Campaign c;
    c.name = QStringLiteral("generated %1 rows").arg(rows);
    c.machine = {
        QStringLiteral("VMC-850"), QStringLiteral("X"), QStringLiteral("generic-modbus"), {}};
    c.screw = Screw{900, 40, 10, -40, QStringLiteral("fixed-free"), 11.5e-6, 7850, 460, 45, {}};
    c.nut_length_mm = 80;
    c.travel_mm = RangeMm{0, 700};
    c.interferometer = Interferometer{150, true, {}};
    const std::vector<std::pair<QString, ChannelRole>> channels{
        {QStringLiteral("T_nut"), ChannelRole::Nut},
        {QStringLiteral("T_bearing_fixed"), ChannelRole::Bearing},
        {QStringLiteral("T_ambient"), ChannelRole::Ambient},
        {QStringLiteral("T_air"), ChannelRole::Air},
        {QStringLiteral("T_bed"), ChannelRole::Structure}};
    for (const auto& [id, role] : channels) {
        c.channels.push_back({id, Quantity::Temperature, role, {}, {}, {}});
        c.sample_columns.push_back(id);
    }
    c.sample_columns.insert(c.sample_columns.end(), {kPositionColumn, kFeedColumn, kTorqueColumn});

    Run run;
    run.id = QStringLiteral("S1");
    run.kind = RunKind::Moving;
    run.feed_mm_min = 8000;
    run.range_mm = RangeMm{210, 490};
    run.samples.columns = c.sample_columns;
    run.samples.values.assign(c.sample_columns.size(), {});
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0.0, 0.02);
    for (std::size_t i = 0; i < rows; ++i) {
        const double t = 0.1 * double(i);
        run.samples.time_s.push_back(t);
        const double rise = 1.0 - std::exp(-t / 1800.0);
        const double values[] = {
            20 + 5 * rise + noise(rng), 20 + 3 * rise + noise(rng),    20 + noise(rng),
            20.1 + noise(rng),          20 + 0.5 * rise + noise(rng),  350 + 140 * std::sin(t),
            8000 * std::cos(t),         1.2 * std::cos(t) + noise(rng)};
        for (std::size_t k = 0; k < c.sample_columns.size(); ++k)
            run.samples.values[k].push_back(values[k]);
    }
    run.motion.push_back({0, 2.1, 210, 490, 8000});
    run.positioning.push_back({0, 0, 0, Direction::Positive, 1.25});
    run.positioning.push_back({2, 0, 700, Direction::Negative, -0.5});
    c.runs.push_back(std::move(run));
    return c;
}

}  // namespace driftlab::test
