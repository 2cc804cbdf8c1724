// The figures read off a step, on responses whose answers are known, and
// the model fit recovering a plant it was given.
#include "tuning/axisplantmodel.h"
#include "tuning/gainproposer.h"
#include "tuning/registerreadback.h"
#include "tuning/stepresponseanalyzer.h"
#include "tuning/tuningresult.h"

#include <QTest>

#include <cmath>

using namespace slew::tuning;
using slew::model::PidGains;

namespace {

StepResponse sampled(double start, double target, double seconds, const std::function<double(double)> &f)
{
    StepResponse s;
    s.start = start;
    s.target = target;
    s.duration = seconds;
    for (double t = 0.02; t <= seconds + 1e-9; t += 0.02)
        s.samples.append({t, f(t)});
    return s;
}

} // namespace

class TestStepResponseAnalyzer : public QObject {
    Q_OBJECT
private slots:
    void firstOrderResponse()
    {
        // x = 1 - e^(-t/τ), τ = 0.5 s: rise 10–90 % is τ·ln 9, 2 % settling is τ·ln 50.
        const double tau = 0.5;
        const StepResponse s = sampled(10, 20, 6, [&](double t) { return 10 + 10 * (1 - std::exp(-t / tau)); });
        const StepMetrics m = StepResponseAnalyzer().analyze(s);
        QVERIFY(m.rose);
        QVERIFY(m.settled);
        QVERIFY(std::fabs(m.riseTime - tau * std::log(9.0)) < 0.03);
        QVERIFY(std::fabs(m.settlingTime - tau * std::log(50.0)) < 0.03);
        QCOMPARE(m.overshootPercent, 0.0);
        QVERIFY(std::fabs(m.steadyStateError) < 0.01);
        QCOMPARE(m.band, 0.2);
    }

    void stepDownWithOvershootAndOffset()
    {
        // Down 4°, 25 % overshoot at 0.5 s, then rests 0.1° short of the target.
        const StepResponse s = sampled(50, 46, 5, [](double t) {
            if (t < 0.5)
                return 50 - 10 * t;          // 45 at 0.5 s: one degree past 46
            if (t < 1.0)
                return 45 + 1.1 * (t - 0.5) / 0.5; // back up to 46.1
            return 46.1;
        });
        const StepMetrics m = StepResponseAnalyzer().analyze(s);
        QVERIFY(std::fabs(m.overshootPercent - 25.0) < 0.6);
        QVERIFY(std::fabs(m.steadyStateError - (-0.1)) < 1e-9);
        QVERIFY(!m.settled); // 0.1° off is outside the 0.08° band
        QCOMPARE(m.settlingTime, 5.0);
    }

    void neverRises()
    {
        const StepResponse s = sampled(0, 10, 2, [](double t) { return t; });
        const StepMetrics m = StepResponseAnalyzer().analyze(s);
        QVERIFY(!m.rose);
        QVERIFY(!m.settled);
        QCOMPARE(formatSeconds(m.riseTime, m.rose), QStringLiteral("—"));
    }

    void fitRecoversThePlant()
    {
        const AxisPlantModel truth{1.3, 0.8};
        const PidGains gains{12, 0, 1};
        QList<double> times;
        for (double t = 0.02; t < 6; t += 0.02)
            times.append(t);
        const QList<double> y = truth.simulate(gains, 0, 4, times);
        StepResponse s;
        s.target = 4;
        s.duration = 6;
        for (qsizetype i = 0; i < y.size(); ++i)
            s.samples.append({times[i], y[i]});
        const PlantFit fit = fitAxisPlant(s, gains);
        QVERIFY(fit.ok);
        QVERIFY2(std::fabs(fit.model.inertia - 1.3) < 0.01, qPrintable(QString::number(fit.model.inertia)));
        QVERIFY2(std::fabs(fit.model.drag - 0.8) < 0.02, qPrintable(QString::number(fit.model.drag)));

        const GainProposal p = GainProposer().propose(fit.model, gains);
        QVERIFY(p.ok);
        QVERIFY(std::fabs(p.damping - 1.0) < 0.02);
        QVERIFY(std::fabs(p.naturalFrequency - std::sqrt(12 / 1.3)) < 0.05);
    }

    void fitRefusesWhatItCannotUse()
    {
        StepResponse s;
        s.target = 4;
        QVERIFY(!fitAxisPlant(s, {12, 0, 1}).ok);
        for (int i = 0; i < 10; ++i)
            s.samples.append({0.1 * i, 0.4 * i});
        const PlantFit zero = fitAxisPlant(s, {0, 0, 1});
        QVERIFY(!zero.ok);
        QVERIFY(zero.error.contains(QStringLiteral("proportional")));
    }

    void registerValuesCompareAtTwoDecimals()
    {
        QCOMPARE(RegisterReadback::format(12.0), QStringLiteral("12"));
        QCOMPARE(RegisterReadback::format(6.29), QStringLiteral("6.29"));
        QCOMPARE(RegisterReadback::format(0.0313), QStringLiteral("0.0313"));
        QVERIFY(RegisterReadback::matches(QStringLiteral("6.29"), QStringLiteral("6.29")));
        QVERIFY(RegisterReadback::matches(QStringLiteral("0.0313"), QStringLiteral("0.03")));
        QVERIFY(!RegisterReadback::matches(QStringLiteral("6.29"), QStringLiteral("6.00")));
    }

    void tableHasEveryFigure()
    {
        TuningResult r;
        r.oldGains = {12, 1, 1};
        r.newGains = {12, 4.1, 6.29};
        r.beforeMetrics.overshootPercent = 47.3;
        r.beforeMetrics.settled = true;
        r.beforeMetrics.settlingTime = 4.76;
        const QString table = formatTuningTable({r});
        for (const char *word : {"rise time", "overshoot", "settling time", "ss error", "kp", "47.3 %", "4.76 s", "6.29"})
            QVERIFY2(table.contains(QLatin1String(word)), word);
        // The header, before and after, and the axis' motion (not measured here).
        QCOMPARE(table.count(u'\n'), 4);
        QVERIFY(table.contains(QLatin1String("az motion: not measured")));
        r.motion = AxisMotion{6.2, 11.5, 0.25, true, {}};
        QVERIFY(formatTuningTable({r}).contains(QStringLiteral("az motion: 6.20°/s, 11.5°/s², response delay 0.25 s")));
    }
};

QTEST_GUILESS_MAIN(TestStepResponseAnalyzer)
#include "tst_stepresponseanalyzer.moc"
