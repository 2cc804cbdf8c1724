// `slew --tune` as a real process against the wall-clock simulator: the
// before/after table on stdout, and clear refusals of bad arguments.
#include <QProcess>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QTest>

class TestSlewTune : public QObject {
    Q_OBJECT

    QString m_bin;

    struct Run {
        int exitCode = -1;
        QString out;
        QString err;
    };

    Run run(const QStringList &args, int timeoutMs)
    {
        QProcess p;
        QSignalSpy done(&p, &QProcess::finished);
        p.start(m_bin, args);
        Run r;
        if (!done.wait(timeoutMs)) {
            p.kill();
            done.wait(5000);
            r.err = QStringLiteral("timed out");
            return r;
        }
        r.exitCode = p.exitCode();
        r.out = QString::fromLocal8Bit(p.readAllStandardOutput());
        r.err = QString::fromLocal8Bit(p.readAllStandardError());
        return r;
    }

    static double figure(const QString &table, const QString &axis, const QString &runName, int column)
    {
        for (const QString &line : table.split(u'\n')) {
            const QStringList cells = line.split(QRegularExpression(QStringLiteral("\\s{2,}|\\s(?=[-\\d>])")),
                                                 Qt::SkipEmptyParts);
            const QStringList words = line.simplified().split(u' ');
            if (words.size() > 2 && words[0] == axis && words[1] == runName) {
                Q_UNUSED(cells);
                // axis run rise "s" overshoot "%" settling "s" ...
                return words.value(column).remove(u'>').toDouble();
            }
        }
        return -1;
    }

private slots:
    void initTestCase()
    {
        // The real slew binary: its main() routes --tune before any window exists.
        m_bin = qEnvironmentVariable("SLEW_BIN");
        QProcess probe;
        QSignalSpy done(&probe, &QProcess::finished);
        probe.start(m_bin, {QStringLiteral("--tune"), QStringLiteral("sim:"), QStringLiteral("--help")});
        QVERIFY(done.wait(15000));
        QVERIFY(QString::fromLocal8Bit(probe.readAllStandardOutput()).contains(QStringLiteral("proposes PID gains")));
        QVERIFY(!m_bin.isEmpty());
    }

    void tunesBothAxesAndPrintsTheTable()
    {
        // The simulator at four times the wall clock: the tuner times its
        // steps on the simulator's clock, and the table matched the 1x run's
        // to 0.02 s (at 8x the coarser polling starts to show).
        const Run r = run({QStringLiteral("--tune"),
                           QStringLiteral("sim:?kp=12&ki=1&kd=1&start_az=100&start_el=30&time_scale=4"),
                           QStringLiteral("--axis"), QStringLiteral("both")},
                          150000);
        qInfo().noquote() << r.out << r.err;
        QCOMPARE(r.exitCode, 0);
        for (const char *word : {"rise time", "overshoot", "settling time", "ss error", "kp", "ki", "kd",
                                 "old gains written back"})
            QVERIFY2(r.out.contains(QLatin1String(word)), word);
        for (const char *axis : {"az", "el"}) {
            const QString a = QLatin1String(axis);
            // Columns: axis run rise s overshoot % settling s ...
            const double before = figure(r.out, a, QStringLiteral("before"), 4);
            const double after = figure(r.out, a, QStringLiteral("after"), 4);
            QVERIFY2(before > 20.0, qPrintable(QStringLiteral("%1 before %2").arg(a).arg(before)));
            QVERIFY2(after >= 0.0 && after < 5.0, qPrintable(QStringLiteral("%1 after %2").arg(a).arg(after)));
        }
    }

    void badArgumentsChangeNothing_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<int>("exitCode");
        QTest::addColumn<QString>("message");
        QTest::newRow("axis") << QStringList{"--tune", "sim:", "--axis", "roll"} << 2 << "--axis must be";
        QTest::newRow("step") << QStringList{"--tune", "sim:", "--step", "90"} << 2 << "--step: 90° is outside 0.5..30°";
        QTest::newRow("step nan") << QStringList{"--tune", "sim:", "--step", "nan"} << 2 << "--step: 'nan' is not a finite number";
        QTest::newRow("uri") << QStringList{"--tune", "sim:?kp=fast"} << 1 << "kp";
        QTest::newRow("dialect") << QStringList{"--tune", "sim:", "--dialect", "gs232"} << 2 << "unknown dialect";
    }
    void badArgumentsChangeNothing()
    {
        QFETCH(QStringList, args);
        QFETCH(int, exitCode);
        QFETCH(QString, message);
        const Run r = run(args, 15000);
        QCOMPARE(r.exitCode, exitCode);
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
    }
};

QTEST_GUILESS_MAIN(TestSlewTune)
#include "tst_slewtune.moc"
