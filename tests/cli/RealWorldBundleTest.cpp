// Bundles as other software writes them (issue 9): Python's csv module with
// every cell quoted, CRLF and a byte-order mark; a European spreadsheet export;
// a tab-separated one with units in the header; two loggers merged row by row;
// a run on a logger's clock; an interferometer's cycles counted from 1 with
// arrows for directions; further columns beside the format's; its columns
// capitalised, with units in brackets; all of them at once with a hand-edited
// campaign.json.
// Each must import through the real driftlab-cli and give the same campaign as
// the plain example (archives and export: BundleArchiveExportTest.cpp).
#include <gtest/gtest.h>
#include <QDir>
#include <QFileInfo>
#include <QTemporaryDir>

#include "core/bundle/BundleReader.h"
#include "tests/cli/RealWorldBundleSupport.h"
#include "tests/support/BundleTestSupport.h"
#include "tests/support/CliRunner.h"

using namespace driftlab;
using namespace driftlab::test;

namespace {

/// Rewrites every CSV of a bundle as Python's csv module writes it for Excel:
/// every cell quoted, CRLF line ends, a UTF-8 byte-order mark.
void rewriteAsQuotedCrlfWithBom(const QString& bundle) {
    const char* script = R"(
import csv, glob, sys
for path in glob.glob(sys.argv[1] + '/*.csv'):
    rows = list(csv.reader(open(path, newline='')))
    with open(path, 'w', newline='', encoding='utf-8-sig') as f:
        csv.writer(f, quoting=csv.QUOTE_ALL, lineterminator='\r\n').writerows(rows)
)";
    runTool(QStringLiteral(DRIFTLAB_PYTHON),
            {QStringLiteral("-c"), QString::fromLatin1(script), bundle});
}

}  // namespace

TEST(RealWorldBundle, quotedCrlfWithByteOrderMarkImportsAsThePlainBundle) {
    QTemporaryDir dir;
    const QString bundle = dir.filePath(QStringLiteral("excel"));
    copyBundle(exampleBundlePath(), bundle);
    rewriteAsQuotedCrlfWithBom(bundle);
    ASSERT_TRUE(readFile(QDir(bundle).filePath(QStringLiteral("samples.csv")))
                    .startsWith("\xEF\xBB\xBF\"run\",\"time_s\""));
    EXPECT_EQ(importedAndExported(bundle, QDir(dir.path())), exampleCampaign());
}

TEST(RealWorldBundle, europeanSpreadsheetExportIsReadWithAWarning) {
    QTemporaryDir dir;
    const QString bundle = dir.filePath(QStringLiteral("european"));
    copyBundle(exampleBundlePath(), bundle);
    const QString samples = QDir(bundle).filePath(QStringLiteral("samples.csv"));
    QByteArray csv = readFile(samples);
    csv.replace(',', ';').replace('.', ',');
    writeFile(samples, csv);
    QByteArray err;
    EXPECT_EQ(importedAndExported(bundle, QDir(dir.path()), &err), exampleCampaign());
    EXPECT_TRUE(err.contains("warning: samples.csv: read as ';'-separated with decimal commas"))
        << err.constData();
}

TEST(RealWorldBundle, twoDevicesLoggedInSeparateRowsAtOneTimeImportAsOneRowEach) {
    // A script that concatenates two loggers' files and sorts by time, without
    // grouping: the thermometers' row and the axis drive's row of each instant
    // follow each other, each with the other's cells empty; and a logger that
    // restarted wrote every 50th row twice.
    QTemporaryDir dir;
    const QString bundle = dir.filePath(QStringLiteral("two-devices"));
    copyBundle(exampleBundlePath(), bundle);
    const char* script = R"(
import csv, sys
path = sys.argv[1] + '/samples.csv'
rows = list(csv.reader(open(path, newline='')))
header, out = rows[0], [rows[0]]
device = [c.startswith('T_') for c in header]
for n, row in enumerate(rows[1:]):
    out.append(row[:2] + [c if device[k] else '' for k, c in enumerate(row) if k >= 2])
    out.append(row[:2] + [c if not device[k] else '' for k, c in enumerate(row) if k >= 2])
    if n % 50 == 0:
        out.append(row)
with open(path, 'w', newline='') as f:
    csv.writer(f, lineterminator='\n').writerows(out)
)";
    // Every instant's second row (542), and the 11 rows written twice.
    expectRewrittenImportsAsThePlainBundle(bundle, script,
                                           "warning: samples.csv:3: 553 row(s) repeat the time of "
                                           "their run's row before and were merged into it");
}

TEST(RealWorldBundle, tabSeparatedWithUnitsInTheHeaderAndTrailingTabsImportsAsThePlainBundle) {
    // A spreadsheet's "text (tab delimited)" export of a sheet whose headers
    // carry units, with a tab closing every line.
    QTemporaryDir dir;
    const QString bundle = dir.filePath(QStringLiteral("tabs"));
    copyBundle(exampleBundlePath(), bundle);
    const char* script = R"(
import csv, glob, sys
unit = {'T': ' [°C]', 'D': ' (µm)', 'S': ' [rpm]'}
for path in glob.glob(sys.argv[1] + '/*.csv'):
    rows = list(csv.reader(open(path, newline='')))
    if path.endswith('samples.csv'):
        rows[0] = [c + unit.get(c[0], '') if c[1:2] == '_' else c for c in rows[0]]
    with open(path, 'w', newline='', encoding='utf-8') as f:
        csv.writer(f, delimiter='\t', lineterminator='\r\n').writerows(r + [''] for r in rows)
)";
    expectRewrittenImportsAsThePlainBundle(
        bundle, script,
        "warning: positioning.csv: read as tab-separated; every line ends with a separator: the "
        "unnamed, empty last column is ignored");
    EXPECT_TRUE(readFile(QDir(bundle).filePath(QStringLiteral("samples.csv")))
                    .startsWith("run\ttime_s\tT_nut [\xC2\xB0"
                                "C]\t"));
}

TEST(RealWorldBundle, aRunOnALoggersClockIsCountedFromItsFirstRecord) {
    // A logger that counts from when it was switched on: run S1 starts at
    // 5000 s in samples.csv, motion.csv and positioning.csv alike. It imports as
    // the plain bundle, counted from its first record, with a warning.
    QTemporaryDir dir;
    const QString bundle = dir.filePath(QStringLiteral("clock"));
    copyBundle(exampleBundlePath(), bundle);
    const char* script = R"(
import csv, sys
for name, columns in (('samples', ['time_s']), ('positioning', ['time_s']),
                      ('motion', ['start_s', 'end_s'])):
    path = sys.argv[1] + '/' + name + '.csv'
    rows = list(csv.reader(open(path, newline='')))
    at = [rows[0].index(c) for c in columns]
    for row in rows[1:]:
        if row[0] == 'S1':
            for i in at: row[i] = '%.3f' % (float(row[i]) + 5000)
    csv.writer(open(path, 'w', newline='')).writerows(rows)
)";
    expectRewrittenImportsAsThePlainBundle(
        bundle, script,
        "warning: run(s) starting late in every file, as on a logger's clock: 'S1' at 5000 s; "
        "counted from their first record");

    // The same on a logger whose clock is Unix time, in seconds since 1970.
    const QString unix = dir.filePath(QStringLiteral("unix"));
    copyBundle(exampleBundlePath(), unix);
    const QByteArray toUnixTime =
        QByteArray(script).replace("float(row[i]) + 5000", "float(row[i]) + 1795000000");
    expectRewrittenImportsAsThePlainBundle(
        unix, toUnixTime.constData(),
        "warning: run(s) starting late in every file, as on a logger's clock: 'S1' at "
        "1795000000 s (the clock read 2026-11-18T11:06:40Z); counted from their first record");

    // And on one that writes the date and time of day, as many loggers do.
    const QString dated = dir.filePath(QStringLiteral("dated"));
    copyBundle(exampleBundlePath(), dated);
    const QByteArray toDateTime = QByteArray(script)
                                      .replace("import csv, sys", "import csv, sys, datetime")
                                      .replace("'%.3f' % (float(row[i]) + 5000)",
                                               "(datetime.datetime(2026, 11, 18, 11, 6, 40) + "
                                               "datetime.timedelta(seconds=float(row[i])))"
                                               ".isoformat(' ', 'milliseconds')");
    expectRewrittenImportsAsThePlainBundle(
        dated, toDateTime.constData(),
        "warning: run(s) starting late in every file, as on a logger's clock: 'S1' at "
        "1795000000 s (the clock read 2026-11-18T11:06:40Z)");
    EXPECT_TRUE(readFile(QDir(dated).filePath(QStringLiteral("positioning.csv")))
                    .contains("\nS1,2026-11-18 11:06:40.000,0,0,+,"));

    // Only the thermometers late, the motion from 0 s: a logger that started
    // late. Its times are kept, and the models name the hole.
    copyBundle(exampleBundlePath(), dir.filePath(QStringLiteral("late")));
    const char* lateLogger = R"(
import csv, sys
path = sys.argv[1] + '/samples.csv'
rows = list(csv.reader(open(path, newline='')))
rows = rows[:1] + [r for r in rows[1:] if r[0] != 'S1' or float(r[1]) >= 900]
csv.writer(open(path, 'w', newline='')).writerows(rows)
)";
    runTool(QStringLiteral(DRIFTLAB_PYTHON), {QStringLiteral("-c"), QString::fromUtf8(lateLogger),
                                              dir.filePath(QStringLiteral("late"))});
    const bundle::BundleReadResult late = bundle::readBundle(dir.filePath(QStringLiteral("late")));
    ASSERT_TRUE(late.ok());
    EXPECT_EQ(late.campaign->findRun(QStringLiteral("S1"))->samples.time_s.front(), 900);
    EXPECT_FALSE(late.warnings.join(QLatin1Char('\n')).contains(QStringLiteral("clock")));
    const CliResult fit = runCli({QStringLiteral("fit"), dir.filePath(QStringLiteral("late")),
                                  QStringLiteral("--model"), QStringLiteral("heat-transfer")});
    EXPECT_NE(fit.exitCode, 0);
    EXPECT_TRUE(fit.err.contains("no sample between 0 s and 900 s")) << fit.err.constData();
}

TEST(RealWorldBundle, cyclesCountedFromOneWithArrowsForDirectionsImportAsThePlainBundle) {
    // An interferometer package's export: measurement cycles counted from 1,
    // directions as ISO 230-2's arrows. It imports as the plain
    // bundle (the first pass is the cold reference), with warnings.
    QTemporaryDir dir;
    const QString bundle = dir.filePath(QStringLiteral("cycles"));
    copyBundle(exampleBundlePath(), bundle);
    const char* script = R"(
import csv, sys
path = sys.argv[1] + '/positioning.csv'
rows = list(csv.reader(open(path, newline='', encoding='utf-8')))
for row in rows[1:]:
    row[2] = str(int(row[2]) + 1)
    row[4] = {'+': '\u2191', '-': '\u2193'}[row[4]]
csv.writer(open(path, 'w', newline='', encoding='utf-8')).writerows(rows)
)";
    expectRewrittenImportsAsThePlainBundle(
        bundle, script,
        "warning: positioning.csv: the cycles of run(s) 'S1' are counted from 1, with no cycle 0: "
        "their first pass, cycle 1, is read as the cold reference (cycle 0)");
    const bundle::BundleReadResult read = bundle::readBundle(bundle);
    ASSERT_TRUE(read.ok());
    EXPECT_TRUE(read.warnings.contains(QStringLiteral(
        "positioning.csv:2: direction written as '↑', '↓': read as + (positive, ↑) and - "
        "(negative, ↓)")))
        << qPrintable(read.warnings.join(QLatin1Char('\n')));

    // A run that lost its cold pass also starts with cycle 1, but warm, at
    // 550 s: it is not renumbered, and the models say what is missing.
    const QString lost = dir.filePath(QStringLiteral("lost"));
    copyBundle(exampleBundlePath(), lost);
    const char* dropColdPass = R"(
import csv, sys
path = sys.argv[1] + '/positioning.csv'
rows = list(csv.reader(open(path, newline='')))
csv.writer(open(path, 'w', newline='')).writerows(rows[:1] + [r for r in rows[1:] if r[2] != '0'])
)";
    runTool(QStringLiteral(DRIFTLAB_PYTHON),
            {QStringLiteral("-c"), QString::fromUtf8(dropColdPass), lost});
    const bundle::BundleReadResult warm = bundle::readBundle(lost);
    ASSERT_TRUE(warm.ok());
    EXPECT_EQ(warm.campaign->findRun(QStringLiteral("S1"))->positioning.front().cycle, 1);
    const CliResult fit =
        runCli({QStringLiteral("fit"), lost, QStringLiteral("--model"), QStringLiteral("mlr")});
    EXPECT_NE(fit.exitCode, 0);
    EXPECT_TRUE(
        fit.err.contains("no run to fit on: run(s) 'S1' have positioning readings but no "
                         "cycle 0 (the cold reference)"))
        << fit.err.constData();
}

TEST(RealWorldBundle, directionsPaddedToAFixedWidthAreThePlainSpelling) {
    // A fixed-width export pads its cells: ' +' and '- ' are + and -, not
    // another spelling to warn about.
    QTemporaryDir dir;
    const QString bundle = dir.filePath(QStringLiteral("padded"));
    copyBundle(exampleBundlePath(), bundle);
    const char* script = R"(
import csv, sys
path = sys.argv[1] + '/positioning.csv'
rows = list(csv.reader(open(path, newline='')))
for row in rows[1:]:
    row[4] = {'+': ' +', '-': '- '}[row[4]]
csv.writer(open(path, 'w', newline='')).writerows(rows)
)";
    expectRewrittenImportsAsThePlainBundle(bundle, script, nullptr);
}

TEST(RealWorldBundle, furtherColumnsOfAnInterferometerExportAreIgnoredWithAWarning) {
    // A laser package writes its environment sensors beside each reading, and
    // a motion log may carry a comment: not part of the format, merely unusual
    // (docs/bundles.md), so the bundle reads.
    QTemporaryDir dir;
    const QString bundle = dir.filePath(QStringLiteral("further"));
    copyBundle(exampleBundlePath(), bundle);
    const char* script = R"(
import csv, sys
d = sys.argv[1] + '/'
rows = list(csv.reader(open(d + 'positioning.csv', newline='')))
rows[0][4:4] = ['air_temp_C']
rows[0] += ['material_temp_C', 'pressure_hPa']
for i, row in enumerate(rows[1:]):
    row[4:4] = ['%.2f' % (20.1 + 0.01 * (i % 7))]
    row += ['%.2f' % (20.4 + 0.01 * (i % 5)), '1013.2']
csv.writer(open(d + 'positioning.csv', 'w', newline='')).writerows(rows)
rows = list(csv.reader(open(d + 'motion.csv', newline='')))
rows[0] = ['comment'] + rows[0]
for i, row in enumerate(rows[1:]):
    row.insert(0, 'dwell, then reverse' if i % 2 else '')
csv.writer(open(d + 'motion.csv', 'w', newline='')).writerows(rows)
)";
    expectRewrittenImportsAsThePlainBundle(
        bundle, script,
        "warning: positioning.csv:1: column(s) 'air_temp_C', 'material_temp_C', 'pressure_hPa' "
        "not part of the format (run,time_s,cycle,target_mm,direction,deviation_um): ignored");
    const bundle::BundleReadResult read = bundle::readBundle(bundle);
    ASSERT_TRUE(read.ok());
    EXPECT_TRUE(read.warnings.contains(
        QStringLiteral("motion.csv:1: column(s) 'comment' not part of the format "
                       "(run,start_s,end_s,from_mm,to_mm,feed_mm_min): ignored")))
        << qPrintable(read.warnings.join(QLatin1Char('\n')));
}

TEST(RealWorldBundle, formatColumnsCapitalisedAndWithTheirUnitInBracketsAreTheFormatsOwn) {
    // Loggers and laser packages write "Time [s]", "Deviation (µm)": the
    // format's columns, once the unit is the format's.
    QTemporaryDir dir;
    const QString bundle = dir.filePath(QStringLiteral("spelled"));
    copyBundle(exampleBundlePath(), bundle);
    const char* script = R"(
import sys
d = sys.argv[1] + '/'
headers = {
    'samples.csv': {'run': 'Run', 'time_s': 'Time [s]', 'position_mm': 'Position [mm]',
                    'feed_mm_min': 'Feed (mm/min)', 'torque_Nm': 'Torque [N\u00b7m]'},
    'positioning.csv': {'run': 'RUN', 'time_s': 'Time (s)', 'cycle': 'Cycle',
                        'target_mm': 'Target [mm]', 'direction': 'Direction',
                        'deviation_um': 'Deviation [\u00b5m]'},
    'motion.csv': {'start_s': 'Start [sec]', 'end_s': 'END_S', 'from_mm': 'From [mm]',
                   'to_mm': 'To [mm]', 'feed_mm_min': 'Feed [mm/min]'},
}
for name, spelled in headers.items():
    lines = open(d + name, encoding='utf-8').read().split('\n')
    lines[0] = ','.join(spelled.get(h, h) for h in lines[0].split(','))
    open(d + name, 'w', encoding='utf-8').write('\n'.join(lines))
)";
    expectRewrittenImportsAsThePlainBundle(bundle, script, nullptr);
    EXPECT_TRUE(readFile(QDir(bundle).filePath(QStringLiteral("positioning.csv")))
                    .startsWith("RUN,Time (s),Cycle,Target [mm],Direction,Deviation [\xC2\xB5m]"));
}

TEST(RealWorldBundle, aForeignExportWithEveryQuirkAtOnceImportsAsThePlainBundle) {
    // The quirks above, together, as one package and one hand-edited file would
    // write them: each repair must leave the others' data alone (the cycles are
    // renumbered on the run's own clock, after the logger's offset is taken off).
    QTemporaryDir dir;
    const QString bundle = dir.filePath(QStringLiteral("foreign"));
    copyBundle(exampleBundlePath(), bundle);
    const char* script = R"(
import csv, json, sys
d = sys.argv[1] + '/'
c = json.load(open(d + 'campaign.json', encoding='utf-8'))
c['screw']['mounting'] = c['screw']['mounting'].title()
for ch in c['channels']:
    ch['role'] = ch['role'].replace('_', '-').title()
for run in c['runs']:
    run['kind'] = run['kind'].upper()
    if 'range_mm' in run:
        run['range_mm'].reverse()
json.dump(c, open(d + 'campaign.json', 'w', encoding='utf-8'), indent=1, ensure_ascii=False)
unit = {'T': ' [°C]', 'D': ' (µm)', 'S': ' [rpm]'}
for name, times in (('samples', [1]), ('positioning', [1]), ('motion', [1, 2])):
    rows = list(csv.reader(open(d + name + '.csv', newline='')))
    for row in rows[1:]:
        if row[0] == 'S1':
            for i in times: row[i] = '%.3f' % (float(row[i]) + 5000)
        if name == 'positioning':
            row[2] = str(int(row[2]) + 1)
            row[4] = {'+': '\u2191', '-': '\u2193'}[row[4]]
    if name == 'samples':
        rows[0] = [h + unit.get(h[0], '') if h[1:2] == '_' else h for h in rows[0]]
    rows = [rows[0]] + [[v.replace('.', ',') for v in row] for row in rows[1:]]
    with open(d + name + '.csv', 'w', newline='', encoding='utf-8-sig') as f:
        csv.writer(f, delimiter=';', lineterminator='\r\n').writerows(rows)
)";
    expectRewrittenImportsAsThePlainBundle(
        bundle, script,
        "warning: positioning.csv: the cycles of run(s) 'S1' are counted from 1, with no cycle 0");
    EXPECT_TRUE(readFile(QDir(bundle).filePath(QStringLiteral("samples.csv")))
                    .startsWith("\xEF\xBB\xBFrun;time_s;T_nut [\xC2\xB0"
                                "C];"));
    EXPECT_TRUE(readFile(QDir(bundle).filePath(QStringLiteral("campaign.json")))
                    .contains("\"kind\": \"SPINDLE\""));
    const bundle::BundleReadResult read = bundle::readBundle(bundle);
    ASSERT_TRUE(read.ok());
    const QString warnings = read.warnings.join(QLatin1Char('\n'));
    for (const char* expected :
         {"samples.csv: read as ';'-separated with decimal commas",
          "run(s) starting late in every file, as on a logger's clock: 'S1' at 5000 s",
          "positioning.csv:2: direction written as '\u2191', '\u2193'"})
        EXPECT_TRUE(warnings.contains(QString::fromUtf8(expected))) << qPrintable(warnings);
}
