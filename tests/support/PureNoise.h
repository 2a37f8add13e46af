#pragma once
// A campaign with no thermal error at all, for the no-harm refusals: every
// positioning reading after cycle 0 becomes its cycle-0 reading plus white
// noise of 1 µm, rewritten in the bundle's positioning.csv by Python.
#include <QString>

#include "tests/support/CliRunner.h"

namespace driftlab::test {

/// Rewrites positioning.csv of the bundle folder `bundle` (seeded: the same each time).
inline void replaceDriftByNoise(const QString& bundle) {
    const char* script = R"(
import csv, random, sys
random.seed(3)
path = sys.argv[1] + '/positioning.csv'
rows = list(csv.reader(open(path, newline='')))
head, rows = rows[0], rows[1:]
c = {k: head.index(k) for k in ('run', 'cycle', 'target_mm', 'direction', 'deviation_um')}
cold = {(r[c['run']], r[c['target_mm']], r[c['direction']]): r[c['deviation_um']]
        for r in rows if int(r[c['cycle']]) == 0}
for r in rows:
    if int(r[c['cycle']]) > 0:
        r[c['deviation_um']] = '%.4f' % (float(cold[(r[c['run']], r[c['target_mm']],
                                                      r[c['direction']])]) + random.gauss(0, 1))
csv.writer(open(path, 'w', newline='')).writerows([head] + rows)
)";
    runTool(QStringLiteral(DRIFTLAB_PYTHON),
            {QStringLiteral("-c"), QString::fromUtf8(script), bundle});
}

}  // namespace driftlab::test
