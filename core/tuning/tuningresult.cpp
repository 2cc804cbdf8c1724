#include "tuningresult.h"

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
    return out;
}

} // namespace slew::tuning
