// history: every campaign of one machine axis in a store, in time order, with
// its ISO 230-2 and ISO 230-3 figures and their trend (docs/history.md).
#include <QJsonArray>
#include <cmath>

#include "app/cli/CliCommon.h"
#include "app/cli/IsoOptions.h"
#include "db/MachineHistoryStore.h"
#include "ui/plots/HistoryPlot.h"

namespace driftlab::cli {
namespace {

QString dateText(const history::CampaignDate& date) {
    return date.utc.toString(Qt::ISODate);
}

QJsonObject figuresJson(const history::MachineHistory& h, std::size_t i,
                        double (history::MachineHistory::*change)(std::size_t, history::Figure)
                            const) {
    QJsonObject o;
    for (history::Figure f : history::kFigures)
        o[history::figureName(f)] = jsonNumber((h.*change)(i, f));
    return o;
}

QJsonObject entryJson(const history::MachineHistory& h, std::size_t i) {
    const history::HistoryEntry& e = h.entries[i];
    QJsonObject positioning{{QStringLiteral("run"), e.positioning.run_id}};
    for (history::Figure f : history::kFigures)
        positioning[history::figureName(f)] = jsonNumber(e.positioning.value_um(f));
    if (!e.positioning.run_note.isEmpty())
        positioning[QStringLiteral("run_note")] = e.positioning.run_note;
    if (!e.positioning.not_determined.isEmpty())
        positioning[QStringLiteral("not_determined")] = e.positioning.not_determined;
    QJsonObject drift{{QStringLiteral("run"), e.drift.run_id}};
    if (e.drift.determined()) {
        drift[QStringLiteral("max_drift_um")] = e.drift.max_drift_um;
        drift[QStringLiteral("range_um")] = e.drift.range_um;
        drift[QStringLiteral("stabilised")] = std::isfinite(e.drift.stabilised_time_s);
        drift[QStringLiteral("stabilised_time_s")] = jsonNumber(e.drift.stabilised_time_s);
    } else {
        drift[QStringLiteral("not_determined")] = e.drift.not_determined;
    }
    return {{QStringLiteral("id"), e.campaign_id},
            {QStringLiteral("name"), e.campaign},
            {QStringLiteral("date"), dateText(e.date)},
            {QStringLiteral("date_source"), e.date.source},
            {QStringLiteral("iso230_2"), positioning},
            {QStringLiteral("change_from_previous"),
             figuresJson(h, i, &history::MachineHistory::changeFromPrevious_um)},
            {QStringLiteral("change_from_first"),
             figuresJson(h, i, &history::MachineHistory::changeFromFirst_um)},
            {QStringLiteral("iso230_3"), drift}};
}

QJsonObject historyJson(const history::MachineHistory& h) {
    QJsonArray campaigns;
    for (std::size_t i = 0; i < h.entries.size(); ++i) campaigns.append(entryJson(h, i));
    const iso::Settings& iso = h.settings.iso;
    return {{QStringLiteral("machine"), h.machine},
            {QStringLiteral("axis"), h.axis},
            {QStringLiteral("standard"), iso::toString(iso.edition)},
            {QStringLiteral("edition"), iso::editionYear(iso.edition)},
            {QStringLiteral("coverage_factor"), iso.coverage_factor},
            {QStringLiteral("window_s"), h.settings.drift.window_s},
            {QStringLiteral("tolerance_um"), h.settings.drift.tolerance_um},
            {QStringLiteral("unit"), QStringLiteral("µm")},
            {QStringLiteral("campaigns"), campaigns}};
}

/// A change with its sign, "n/a" where there is none.
QString changeText(double value_um) {
    if (!std::isfinite(value_um)) return QStringLiteral("n/a");
    return (value_um >= 0 ? QStringLiteral("+") : QString()) + umText(value_um);
}

void printHistory(const history::MachineHistory& h) {
    const iso::Settings& iso = h.settings.iso;
    printLine(QStringLiteral("Machine history of %1 axis %2: %3 campaign(s), oldest first; %4, "
                             "k = %5; drift: stabilised = varies by less than %6 µm over every "
                             "%7 s window")
                  .arg(h.machine, h.axis)
                  .arg(h.entries.size())
                  .arg(iso::toString(iso.edition))
                  .arg(iso.coverage_factor)
                  .arg(h.settings.drift.tolerance_um)
                  .arg(h.settings.drift.window_s));
    printLine(QString());
    QString head = QStringLiteral("%1  %2 %3")
                       .arg(QStringLiteral("date"), -10)
                       .arg(QStringLiteral("campaign"), -24)
                       .arg(QStringLiteral("run"), -6);
    for (history::Figure f : history::kFigures)
        head += QStringLiteral("%1").arg(history::figureName(f) + QStringLiteral(" µm"), 10);
    printLine(head + QStringLiteral("  max drift µm  range µm  stabilised"));
    for (const history::HistoryEntry& e : h.entries) {
        QString line =
            QStringLiteral("%1  %2 %3")
                .arg(e.date.utc.toString(QStringLiteral("yyyy-MM-dd")))
                .arg(QStringLiteral("%1 %2").arg(e.campaign_id).arg(e.campaign).left(24), -24)
                .arg(e.positioning.run_id.isEmpty() ? QStringLiteral("—")
                                                    : e.positioning.run_id.left(6),
                     -6);
        for (history::Figure f : history::kFigures)
            line += QStringLiteral("%1").arg(umText(e.positioning.value_um(f)), 10);
        if (e.drift.determined())
            line += QStringLiteral("%1%2  %3")
                        .arg(umText(e.drift.max_drift_um), 14)
                        .arg(umText(e.drift.range_um), 10)
                        .arg(std::isfinite(e.drift.stabilised_time_s)
                                 ? QStringLiteral("%1 s").arg(e.drift.stabilised_time_s)
                                 : QStringLiteral("not stabilised"));
        else
            line += QStringLiteral("%1").arg(QStringLiteral("n/a"), 14);
        printLine(line);
    }
    printLine(QString());
    printLine(
        QStringLiteral("change, µm        from the previous campaign              "
                       "     from the first campaign"));
    QString changeHead = QStringLiteral("campaign          ");
    for (int part = 0; part < 2; ++part)
        for (history::Figure f : history::kFigures)
            changeHead += QStringLiteral("%1").arg(history::figureName(f), 8);
    printLine(changeHead);
    for (std::size_t i = 0; i < h.entries.size(); ++i) {
        QString line = QStringLiteral("%1").arg(h.entries[i].campaign_id, -18);
        for (history::Figure f : history::kFigures)
            line += QStringLiteral("%1").arg(changeText(h.changeFromPrevious_um(i, f)), 8);
        for (history::Figure f : history::kFigures)
            line += QStringLiteral("%1").arg(changeText(h.changeFromFirst_um(i, f)), 8);
        printLine(line);
    }
    printLine(QString());
    for (const history::HistoryEntry& e : h.entries) {
        printLine(QStringLiteral("campaign %1 '%2': dated %3 (%4)")
                      .arg(e.campaign_id)
                      .arg(e.campaign, dateText(e.date), e.date.source));
        if (!e.positioning.run_note.isEmpty())
            printLine(QStringLiteral("  ") + e.positioning.run_note);
        if (!e.positioning.not_determined.isEmpty())
            printLine(QStringLiteral("  ISO 230-2 not determined: ") +
                      e.positioning.not_determined);
        if (!e.drift.determined())
            printLine(QStringLiteral("  ISO 230-3 not determined: ") + e.drift.not_determined);
    }
}

}  // namespace

int historyCommand(const QStringList& args) {
    QCommandLineParser parser;
    const QCommandLineOption dbOption{
        QStringLiteral("db"),
        QStringLiteral("Campaign store: a SQLite file, or postgresql://USER@HOST[:PORT]/DB."),
        QStringLiteral("FILE")};
    const QCommandLineOption machine{QStringLiteral("machine"),
                                     QStringLiteral("The machine, as campaign.json machine.name."),
                                     QStringLiteral("M")};
    const QCommandLineOption axis{QStringLiteral("axis"),
                                  QStringLiteral("The axis, as campaign.json machine.axis."),
                                  QStringLiteral("X")};
    const QCommandLineOption edition = isoEditionOption();
    const QCommandLineOption coverage = isoCoverageOption();
    const QCommandLineOption png{QStringLiteral("png"),
                                 QStringLiteral("Also write the trend of A, E, R, B, M against "
                                                "the campaign date as a PNG file."),
                                 QStringLiteral("FILE")};
    parseArguments(parser, args, {dbOption, machine, axis, edition, coverage, png},
                   Arguments{{}, {}, {}, {dbOption, machine, axis}});
    history::HistorySettings settings;
    settings.iso = isoSettings(parser);

    auto store = openSourceStore(parser, db::StoreAccess::ReadOnly);
    QString error;
    const auto h =
        db::machineHistory(*store, parser.value(machine), parser.value(axis), settings, &error);
    if (!h) throw CliError(error);
    if (parser.isSet(png)) {
        if (!ui::saveCurvesPng(ui::historyTrendPlot(*h), parser.value(png), &error))
            throw CliError(error);
    }
    if (parser.isSet(QStringLiteral("json"))) {
        printJson(historyJson(*h));
        return 0;
    }
    printHistory(*h);
    if (parser.isSet(png)) printLine(QStringLiteral("wrote ") + parser.value(png));
    return 0;
}

}  // namespace driftlab::cli
