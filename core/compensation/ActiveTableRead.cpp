#include "core/compensation/ActiveTableRead.h"

#include <QList>
#include <QRegularExpression>
#include <cmath>
#include <limits>

#include "core/compensation/CsvExport.h"
#include "core/compensation/FormatOptions.h"

namespace driftlab::compensation {
namespace {

/// The text's lines without line ends; blank lines kept so that numbers
/// match the file.
QList<QByteArray> linesOf(const QByteArray& text) {
    QList<QByteArray> lines = text.split('\n');
    for (QByteArray& line : lines) line = line.trimmed();
    if (!lines.isEmpty() && lines.back().isEmpty()) lines.removeLast();
    return lines;
}

std::optional<double> number(const QByteArray& field) {
    bool ok = false;
    const double value = field.trimmed().toDouble(&ok);
    if (!ok || !std::isfinite(value)) return std::nullopt;
    return value;
}

QString at(const QString& where, qsizetype line) {
    return QStringLiteral("%1:%2: ").arg(where).arg(line + 1);
}

void addPoint(CompensationTable& table, double position_mm, double plus_um, double minus_um) {
    table.position_mm.push_back(position_mm);
    table.correction_plus_um.push_back(plus_um);
    table.correction_minus_um.push_back(minus_um);
}

ActiveTableRead readCsv(const QList<QByteArray>& lines, const QString& where) {
    ActiveTableRead read;
    const QList<QByteArray> header = lines.front().split(',');
    // Which sign and mode the columns hold: their names say it (CsvExport.h).
    int plusColumn = -1, minusColumn = -1;
    ValueSign sign = ValueSign::Correction;
    ValueMode mode = ValueMode::Absolute;
    for (ValueSign s : {ValueSign::Correction, ValueSign::Error})
        for (ValueMode m : {ValueMode::Absolute, ValueMode::Incremental}) {
            const QByteArray name = csvValueColumn(s, m);
            const int plus = int(header.indexOf(name + "_um"));
            if (plus < 0) continue;
            plusColumn = plus;
            minusColumn = int(header.indexOf(name + "_minus_um"));
            sign = s;
            mode = m;
        }
    if (header.value(0) != "position_mm" || plusColumn < 0) {
        read.error =
            at(where, 0) + QStringLiteral(
                               "not a DriftLab table: the header must be position_mm and a "
                               "correction_um, error_um, correction_increment_um or "
                               "error_increment_um column");
        return read;
    }
    double plusSum = 0, minusSum = 0;
    for (qsizetype i = 1; i < lines.size(); ++i) {
        const QList<QByteArray> fields = lines[i].split(',');
        if (fields.size() != header.size()) {
            read.error = at(where, i) + QStringLiteral("%1 fields, the header has %2")
                                            .arg(fields.size())
                                            .arg(header.size());
            return read;
        }
        const auto x = number(fields[0]);
        const auto plus = number(fields[plusColumn]);
        const auto minus = minusColumn >= 0 ? number(fields[minusColumn]) : plus;
        if (!x || !plus || !minus) {
            read.error = at(where, i) + QStringLiteral("'%1' is not a row of finite numbers")
                                            .arg(QString::fromUtf8(lines[i]));
            return read;
        }
        plusSum = mode == ValueMode::Incremental ? plusSum + *plus : *plus;
        minusSum = mode == ValueMode::Incremental ? minusSum + *minus : *minus;
        addPoint(read.table, *x, signedValue(plusSum, sign), signedValue(minusSum, sign));
    }
    read.table.bidirectional = minusColumn >= 0;
    read.layout = QStringLiteral("DriftLab CSV (%1, %2)").arg(signName(sign), modeName(mode));
    return read;
}

ActiveTableRead readLinuxCnc(const QList<QByteArray>& lines, bool type0, const QString& where) {
    ActiveTableRead read;
    static const QRegularExpression space(QStringLiteral("\\s+"));
    for (qsizetype i = 0; i < lines.size(); ++i) {
        // LinuxCNC itself stops silently at the first line that is not three
        // numbers; a table read back must not lose its end that way.
        const QStringList fields = QString::fromLatin1(lines[i]).split(space, Qt::SkipEmptyParts);
        std::optional<double> v[3];
        for (int k = 0; k < 3 && k < fields.size(); ++k) v[k] = number(fields[k].toLatin1());
        if (fields.size() != 3 || !v[0] || !v[1] || !v[2]) {
            read.error = at(where, i) +
                         QStringLiteral(
                             "'%1' is not 'nominal second third' (LinuxCNC would stop reading "
                             "the table here)")
                             .arg(QString::fromLatin1(lines[i]));
            return read;
        }
        // Type 0: actual positions, trim = nominal − actual; type 1: trims.
        const double plus_mm = type0 ? *v[0] - *v[1] : *v[1];
        const double minus_mm = type0 ? *v[0] - *v[2] : *v[2];
        addPoint(read.table, *v[0], plus_mm * 1000, minus_mm * 1000);
    }
    read.table.bidirectional = read.table.correction_plus_um != read.table.correction_minus_um;
    read.layout = type0 ? QStringLiteral("LinuxCNC COMP_FILE_TYPE 0")
                        : QStringLiteral("LinuxCNC COMP_FILE_TYPE 1");
    return read;
}

ActiveTableRead readSinumerik(const QList<QByteArray>& lines, const QString& where) {
    ActiveTableRead read;
    static const QRegularExpression value(
        QStringLiteral("^\\$AA_ENC_COMP\\[\\s*\\d+\\s*,\\s*(\\d+)\\s*,[^\\]]+\\]\\s*=\\s*(\\S+)"));
    static const QRegularExpression step(
        QStringLiteral("^\\$AA_ENC_COMP_STEP\\[[^\\]]+\\]\\s*=\\s*(\\S+)"));
    static const QRegularExpression minimum(
        QStringLiteral("^\\$AA_ENC_COMP_MIN\\[[^\\]]+\\]\\s*=\\s*(\\S+)"));
    std::vector<double> error_mm;
    std::optional<double> step_mm, min_mm;
    for (qsizetype i = 0; i < lines.size(); ++i) {
        const QString line = QString::fromLatin1(lines[i]);
        QRegularExpressionMatch m;
        if ((m = value.match(line)).hasMatch()) {
            const auto v = number(m.captured(2).toLatin1());
            if (!v || m.captured(1).toLongLong() != qlonglong(error_mm.size())) {
                read.error =
                    at(where, i) + QStringLiteral("'%1': expected the finite value of point %2")
                                       .arg(line)
                                       .arg(error_mm.size());
                return read;
            }
            error_mm.push_back(*v);
        } else if ((m = step.match(line)).hasMatch()) {
            step_mm = number(m.captured(1).toLatin1());
        } else if ((m = minimum.match(line)).hasMatch()) {
            min_mm = number(m.captured(1).toLatin1());
        }
    }
    if (!step_mm || !min_mm || !(*step_mm > 0)) {
        read.error = where + QStringLiteral(
                                 ": no positive $AA_ENC_COMP_STEP and finite "
                                 "$AA_ENC_COMP_MIN: the points have no positions");
        return read;
    }
    // The EEC table holds +deviation (the sign Sinumerik corrects by).
    for (std::size_t i = 0; i < error_mm.size(); ++i)
        addPoint(read.table, *min_mm + double(i) * *step_mm, -error_mm[i] * 1000,
                 -error_mm[i] * 1000);
    read.layout = QStringLiteral("Sinumerik $AA_ENC_COMP");
    return read;
}

ActiveTableRead readHeidenhain(const QList<QByteArray>& lines, ValueSign sign,
                               const QString& where) {
    ActiveTableRead read;
    static const QRegularExpression space(QStringLiteral("\\s+"));
    bool inRows = false, hasBacklash = false;
    for (qsizetype i = 0; i < lines.size(); ++i) {
        const QStringList fields = QString::fromLatin1(lines[i]).split(space, Qt::SkipEmptyParts);
        if (fields.isEmpty() || fields.front().startsWith(QLatin1String("BEGIN"))) continue;
        if (fields.front() == QLatin1String("[END]")) break;
        if (fields.front() == QLatin1String("NR")) {
            inRows = true;
            continue;
        }
        std::optional<double> v[4];
        for (int k = 0; k < 4 && k < fields.size(); ++k) v[k] = number(fields[k].toLatin1());
        if (!inRows || fields.size() != 4 || !v[1] || !v[2] || !v[3]) {
            read.error =
                at(where, i) + QStringLiteral("'%1' is not a row NR AXISPOS value BACKLASH")
                                   .arg(QString::fromLatin1(lines[i]));
            return read;
        }
        hasBacklash = hasBacklash || *v[3] != 0;
        // The − approach's value is the + value plus BACKLASH, in the file's sign.
        addPoint(read.table, *v[1], signedValue(*v[2] * 1000, sign),
                 signedValue((*v[2] + *v[3]) * 1000, sign));
    }
    read.table.bidirectional = hasBacklash;
    read.layout = QStringLiteral("Heidenhain .COM (%1)").arg(signName(sign));
    return read;
}

}  // namespace

ActiveTableRead readActiveTable(const QByteArray& text, const QString& format,
                                std::optional<ValueSign> sign, const QString& where) {
    const QList<QByteArray> lines = linesOf(text);
    ActiveTableRead read;
    if (lines.isEmpty()) {
        read.error = where + QStringLiteral(": the file is empty");
        return read;
    }
    if (lines.front().startsWith("position_mm,"))
        read = readCsv(lines, where);
    else if (format == QLatin1String("linuxcnc") || format == QLatin1String("linuxcnc-type1"))
        read = readLinuxCnc(lines, format == QLatin1String("linuxcnc"), where);
    else if (format == QLatin1String("sinumerik"))
        read = readSinumerik(lines, where);
    else if (format == QLatin1String("heidenhain"))
        read = readHeidenhain(lines, effectiveSign(format, sign), where);
    else if (format.isEmpty())
        read.error = where + QStringLiteral(
                                 ": not a DriftLab CSV table (position_mm,...), and no --format "
                                 "to read it as a controller's file");
    else
        read.error = where + QStringLiteral(
                                 ": a %1 table cannot be read back (Fanuc pitch data are "
                                 "increments without the value at the reference point): give "
                                 "the active table as DriftLab CSV")
                                 .arg(format);
    if (!read.ok()) return read;
    // Same shape checks as any table, no value limits: the active table is
    // what the controller holds, whatever it is.
    const double none = std::numeric_limits<double>::infinity();
    const QString malformed = validate(read.table, Limits{none, none, none}, 1024);
    if (!malformed.isEmpty()) read.error = where + QStringLiteral(": ") + malformed;
    return read;
}

}  // namespace driftlab::compensation
