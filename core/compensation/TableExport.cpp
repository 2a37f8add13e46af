#include "core/compensation/TableExport.h"

#include "core/compensation/CsvExport.h"
#include "core/compensation/FanucExport.h"
#include "core/compensation/HeidenhainExport.h"
#include "core/compensation/LinuxCncExport.h"
#include "core/compensation/SinumerikExport.h"

namespace driftlab::compensation {
namespace {

bool isFanuc(const QString& format) {
    return format == QLatin1String("fanuc") || format == QLatin1String("fanuc-g10");
}

}  // namespace

QStringList tableFormats() {
    return {QStringLiteral("linuxcnc"),  QStringLiteral("linuxcnc-type1"),
            QStringLiteral("fanuc"),     QStringLiteral("fanuc-g10"),
            QStringLiteral("sinumerik"), QStringLiteral("heidenhain"),
            QStringLiteral("csv")};
}

QString checkTableExport(const QString& format, const TableExportSettings& settings) {
    if (!tableFormats().contains(format))
        return QStringLiteral("format '%1' is not one of %2")
            .arg(format, tableFormats().join(QStringLiteral(", ")));
    if (settings.magnification < 1)
        return QStringLiteral("magnification: %1 is not a whole number of at least 1")
            .arg(settings.magnification);
    if (isFanuc(format) && !settings.axis.isEmpty()) {
        bool ok = false;
        const int axis = settings.axis.toInt(&ok);
        if (!ok || axis < 1)
            return QStringLiteral(
                       "axis: Fanuc takes a controlled axis number (1, 2, ...), not "
                       "'%1'")
                .arg(settings.axis);
    }
    return {};
}

ExportResult exportTable(const CompensationTable& table, const QString& format,
                         const TableExportSettings& settings) {
    ExportResult refused;
    refused.error = checkTableExport(format, settings);
    if (!refused.ok()) return refused;
    if (format == QLatin1String("linuxcnc")) return exportLinuxCnc(table, LinuxCncType::Type0);
    if (format == QLatin1String("linuxcnc-type1"))
        return exportLinuxCnc(table, LinuxCncType::Type1);
    if (format == QLatin1String("csv")) return exportCsv(table);
    if (format == QLatin1String("sinumerik")) {
        SinumerikSettings sinumerik;
        if (!settings.axis.isEmpty()) sinumerik.axis = settings.axis;
        return exportSinumerik(table, sinumerik);
    }
    if (format == QLatin1String("heidenhain")) {
        HeidenhainSettings heidenhain;
        // The campaign names its axis; the .COM column is that axis's key.
        const QString name = !settings.axis.isEmpty()            ? settings.axis
                             : !settings.campaign_axis.isEmpty() ? settings.campaign_axis
                                                                 : heidenhain.axis;
        heidenhain.axis = name;
        heidenhain.table_name = name + QStringLiteral(".COM");
        return exportHeidenhain(table, heidenhain);
    }
    FanucSettings fanuc;
    fanuc.magnification = settings.magnification;
    if (!settings.axis.isEmpty()) fanuc.axis = settings.axis.toInt();
    return format == QLatin1String("fanuc") ? exportFanucParameters(table, fanuc)
                                            : exportFanucG10(table, fanuc);
}

}  // namespace driftlab::compensation
