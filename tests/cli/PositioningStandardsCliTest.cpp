// driftlab-cli iso230-2 --standard as scripts use it: every standard side by
// side on the hand-worked golden readings (tests/iso/Iso230TestData.h, G1),
// the default evaluation unchanged, and the refusals of standards left out.

#include <gtest/gtest.h>

#include <QJsonArray>
#include <QJsonObject>

#include "tests/support/CliRunner.h"

using namespace driftlab::test;

// Named, not anonymous: the unity build puts the CLI tests in one file.
namespace standards_cli {

const QString kGoldenReadings =
    QStringLiteral(DRIFTLAB_SOURCE_DIR "/tests/iso/data/golden_3x5.csv");

CliResult isoGolden(QStringList args) {
    return runCli(QStringList{QStringLiteral("iso230-2"), kGoldenReadings} + args);
}

QJsonObject standardOf(const QJsonObject& comparison, const QString& id) {
    for (const QJsonValue& s : comparison.value(QStringLiteral("standards")).toArray())
        if (s.toObject().value(QStringLiteral("id")).toString() == id) return s.toObject();
    ADD_FAILURE() << "no standard " << qPrintable(id);
    return {};
}

}  // namespace standards_cli

using namespace standards_cli;

TEST(PositioningStandardsCli, allJsonComparesEveryStandardWithTheGoldenValues) {
    const CliResult r =
        isoGolden({QStringLiteral("--standard"), QStringLiteral("all"), QStringLiteral("--json")});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    const QJsonObject o = json(r);
    EXPECT_EQ(o.value(QStringLiteral("unit")).toString(), QStringLiteral("µm"));
    EXPECT_EQ(o.value(QStringLiteral("source")).toString(), kGoldenReadings);
    QStringList ids;
    for (const QJsonValue& s : o.value(QStringLiteral("standards")).toArray())
        ids << s.toObject().value(QStringLiteral("id")).toString();
    EXPECT_EQ(ids, (QStringList{"iso230-2:2014", "iso230-2:2006", "iso230-2:1997", "gbt17421.2",
                                "jis-b0182"}));

    // G1 by ISO 230-2, k = 2: R = 2 + 2 + 5 = 9 at 0 mm, A = 6 − (−6) = 12.
    for (const QString& id : {QStringLiteral("iso230-2:2014"), QStringLiteral("gbt17421.2")}) {
        const QJsonObject s = standardOf(o, id);
        const QJsonObject values = s.value(QStringLiteral("values")).toObject();
        EXPECT_EQ(values.size(), 12) << qPrintable(id);
        EXPECT_DOUBLE_EQ(values.value(QStringLiteral("R")).toDouble(), 9) << qPrintable(id);
        EXPECT_DOUBLE_EQ(values.value(QStringLiteral("A")).toDouble(), 12) << qPrintable(id);
        EXPECT_DOUBLE_EQ(values.value(QStringLiteral("B")).toDouble(), 5) << qPrintable(id);
        EXPECT_EQ(s.value(QStringLiteral("coverage_factor")).toDouble(), 2) << qPrintable(id);
        EXPECT_EQ(s.value(QStringLiteral("min_approaches")).toInt(), 5) << qPrintable(id);
    }
    // By JIS B 0182, k = 3: R = 3 + 3 + 5 = 11; it defines no accuracy.
    const QJsonObject jis = standardOf(o, QStringLiteral("jis-b0182"));
    const QJsonObject jisValues = jis.value(QStringLiteral("values")).toObject();
    EXPECT_EQ(jisValues.keys(), (QStringList{"B", "R"}));
    EXPECT_DOUBLE_EQ(jisValues.value(QStringLiteral("R")).toDouble(), 11);
    EXPECT_DOUBLE_EQ(jisValues.value(QStringLiteral("B")).toDouble(), 5);
    EXPECT_EQ(jis.value(QStringLiteral("coverage_factor")).toDouble(), 3);
    EXPECT_EQ(jis.value(QStringLiteral("min_approaches")).toInt(), 0);

    QStringList leftOut;
    for (const QJsonValue& s : o.value(QStringLiteral("not_evaluated")).toArray()) {
        leftOut << s.toObject().value(QStringLiteral("id")).toString();
        EXPECT_FALSE(s.toObject().value(QStringLiteral("why")).toString().isEmpty());
    }
    EXPECT_EQ(leftOut, (QStringList{"vdi3441", "asme-b5.54", "jis-b6192"}));
    // The two warnings of G1 (three targets; the common swing), each once.
    EXPECT_EQ(o.value(QStringLiteral("warnings")).toArray().size(), 2);
}

TEST(PositioningStandardsCli, allTextPutsTheStandardsInColumns) {
    const CliResult r = isoGolden({QStringLiteral("--standard"), QStringLiteral("all")});
    ASSERT_EQ(r.exitCode, 0) << r.err.constData();
    const QString text = QString::fromUtf8(r.out);
    // The figures of the row that starts with `label`, the symbol and two
    // words of its meaning skipped.
    const auto figures = [&](const QString& label) {
        for (const QString& line : text.split(QLatin1Char('\n')))
            if (line.startsWith(label))
                return line.split(QLatin1Char(' '), Qt::SkipEmptyParts).mid(3);
        return QStringList{};
    };
    // ISO 230-2 three editions, GB/T 17421.2: 9; JIS B 0182: 11.
    EXPECT_EQ(figures(QStringLiteral("  R    ")),
              (QStringList{"9.000", "9.000", "9.000", "9.000", "11.000"}))
        << qPrintable(text);
    // A is not defined by the JIS vocabulary.
    EXPECT_EQ(figures(QStringLiteral("  A    ")),
              (QStringList{"12.000", "12.000", "12.000", "12.000", "-"}))
        << qPrintable(text);
    EXPECT_TRUE(text.contains(QStringLiteral("VDI/DGQ 3441"))) << qPrintable(text);
}

TEST(PositioningStandardsCli, isoStandardIsTheDefaultEvaluation) {
    const CliResult plain = isoGolden({QStringLiteral("--json")});
    const CliResult named = isoGolden(
        {QStringLiteral("--standard"), QStringLiteral("iso230-2:2014"), QStringLiteral("--json")});
    ASSERT_EQ(plain.exitCode, 0) << plain.err.constData();
    ASSERT_EQ(named.exitCode, 0) << named.err.constData();
    EXPECT_EQ(named.out, plain.out);
    const CliResult edition = isoGolden(
        {QStringLiteral("--standard"), QStringLiteral("iso230-2:1997"), QStringLiteral("--json")});
    ASSERT_EQ(edition.exitCode, 0) << edition.err.constData();
    EXPECT_EQ(json(edition).value(QStringLiteral("edition")).toInt(), 1997);
}

TEST(PositioningStandardsCli, leftOutAndUnknownStandardsAreRefusedWithTheReason) {
    const CliResult vdi = isoGolden({QStringLiteral("--standard"), QStringLiteral("vdi3441")});
    EXPECT_EQ(vdi.exitCode, 2);
    EXPECT_TRUE(reason(vdi.err).contains("VDI/DGQ 3441 is not evaluated")) << vdi.err.constData();
    const CliResult unknown = isoGolden({QStringLiteral("--standard"), QStringLiteral("nmtba")});
    EXPECT_EQ(unknown.exitCode, 2);
    EXPECT_TRUE(reason(unknown.err).contains("jis-b0182")) << unknown.err.constData();
    // JIS B 0182 fixes k = 3: another k is refused, not silently ignored.
    const CliResult k = isoGolden({QStringLiteral("--standard"), QStringLiteral("jis-b0182"),
                                   QStringLiteral("--coverage-factor"), QStringLiteral("2")});
    EXPECT_EQ(k.exitCode, 2);
    EXPECT_TRUE(reason(k.err).contains("--coverage-factor")) << k.err.constData();
    const CliResult clash =
        isoGolden({QStringLiteral("--standard"), QStringLiteral("iso230-2:2006"),
                   QStringLiteral("--edition"), QStringLiteral("2014")});
    EXPECT_EQ(clash.exitCode, 2);
}
