#include "tuningresult.h"

#include <algorithm>

namespace slew::tuning {

QString axisName(session::Axis axis)
{
    return axis == session::Axis::Azimuth ? QStringLiteral("az") : QStringLiteral("el");
}

int firstGainRegister(session::Axis axis)
{
    return axis == session::Axis::Azimuth ? 1 : 4;
}

namespace {

QString cell(const QString &text, int width)
{
    return text.leftJustified(width);
}

QString number(double v)
{
    return QString::number(v, 'g', 4);
}

} // namespace

QString formatTuningTable(const QList<TuningResult> &results)
{
    const QList<int> widths{5, 8, 11, 11, 15, 11, 9, 9, 9};
    const QStringList header{"axis", "run", "rise time", "overshoot", "settling time", "ss error", "kp", "ki", "kd"};
    QString out;
    auto row = [&](const QStringList &cells) {
        QString line;
        for (int i = 0; i < cells.size(); ++i)
            line += i + 1 < cells.size() ? cell(cells[i], widths[i]) : cells[i];
        out += line.trimmed() + u'\n';
    };
    row(header);
    for (const TuningResult &r : results) {
        auto figures = [&](const QString &run, const StepMetrics &m, const model::PidGains &g) {
            row({axisName(r.axis), run, formatSeconds(m.riseTime, m.rose),
                 QStringLiteral("%1 %").arg(m.overshootPercent, 0, 'f', 1),
                 m.settled ? formatSeconds(m.settlingTime, true)
                           : QStringLiteral(">%1 s").arg(m.settlingTime, 0, 'f', 1),
                 QStringLiteral("%1°").arg(m.steadyStateError, 0, 'f', 3), number(g.kp), number(g.ki), number(g.kd)});
        };
        figures(QStringLiteral("before"), r.beforeMetrics, r.oldGains);
        figures(QStringLiteral("after"), r.afterMetrics, r.newGains);
    }
    for (const TuningResult &r : results) {
        const AxisMotion &m = r.motion;
        out += m.ok ? QStringLiteral("%1 motion: %2°/s, %3°/s², response delay %4 s\n")
                          .arg(axisName(r.axis))
                          .arg(m.speedDegS, 0, 'f', 2)
                          .arg(m.accelDegS2, 0, 'f', 1)
                          .arg(m.responseDelayS, 0, 'f', 2)
                    : QStringLiteral("%1 motion: not measured (%2)\n").arg(axisName(r.axis), m.error);
    }
    return out;
}

model::RotatorMotion withMeasuredMotion(model::RotatorMotion motion, const TuningResult &result)
{
    const AxisMotion &m = result.motion;
    if (!m.ok)
        return motion;
    const bool az = result.axis == session::Axis::Azimuth;
    (az ? motion.azSpeedDegS : motion.elSpeedDegS) = m.speedDegS;
    (az ? motion.azAccelDegS2 : motion.elAccelDegS2) = m.accelDegS2;
    motion.responseDelayS = m.responseDelayS;
    return motion;
}

} // namespace slew::tuning
