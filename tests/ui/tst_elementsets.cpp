// SPDX-License-Identifier: GPL-3.0-or-later
// Sky → Element sets…: sources typed in the window are fetched from a web
// server the test runs on 127.0.0.1 (never the internet) or read from a
// file, each source shows its state and the age of its sets, sets older
// than the limit are named, a line that is not a URL is refused by number,
// and the next window starts from the cache with no network.

#include "../common/tinyhttpserver.h"
#include "windowfixture.h"

#include "sky/elementsetsources.h"
#include "tracking/elementsetsdialog.h"

#include <QAction>
#include <QDateTime>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeWidget>

namespace {

// The line's modulo-10 checksum: digits count their value, '-' counts 1.
char checksum(const QByteArray &line)
{
    int sum = 0;
    for (char c : line.left(68))
        sum += (c >= '0' && c <= '9') ? c - '0' : (c == '-' ? 1 : 0);
    return char('0' + sum % 10);
}

// The ISS's elements with the epoch moved to a moment `daysAgo` before now.
QByteArray issEpochDaysAgo(double daysAgo)
{
    const QDateTime when = QDateTime::currentDateTimeUtc().addMSecs(qint64(-daysAgo * 86400000.0));
    const double dayOfYear = when.date().dayOfYear() + when.time().msecsSinceStartOfDay() / 86400000.0;
    QByteArray line1 = "1 25544U 98067A   08264.51782528 -.00002182  00000-0 -11606-4 0  2927";
    const QByteArray epoch = QByteArray::number(when.date().year() % 100).rightJustified(2, '0')
        + QByteArray::number(dayOfYear, 'f', 8).rightJustified(12, '0');
    line1.replace(18, 14, epoch);
    line1[68] = checksum(line1);
    return "ISS (ZARYA)\n" + line1 + "\n2 25544  51.6416 247.4627 0006703 130.5360 325.0288 15.72125391563537\n";
}

const QByteArray kNoaa2018 = "NOAA 19\n"
                             "1 33591U 09005A   18020.91958580  .00000107  00000-0  83477-4 0  9992\n"
                             "2 33591  99.1238 356.1693 0014450  24.0615 336.1228 14.12247534461122\n";

slew::ui::ElementSetsDialog *openDialog(WindowFixture &f)
{
    f.find<QAction>(QStringLiteral("actionElementSets"))->trigger();
    return f.find<slew::ui::ElementSetsDialog>(QStringLiteral("elementSetsDialog"));
}

} // namespace

class TestElementSets : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { WindowFixture::prepareApplication(); }

    void fetchesShowsAgesAndNamesStaleSets()
    {
        TinyHttpServer server;
        QVERIFY(server.listen(QHostAddress::LocalHost, 0));
        server.pages.insert("/stations.txt", issEpochDaysAgo(2.0));
        server.pages.insert("/weather.txt", kNoaa2018);

        WindowFixture f;
        auto *dialog = openDialog(f);
        QVERIFY(dialog);
        auto *urls = dialog->findChild<QPlainTextEdit *>(QStringLiteral("elementSetUrls"));
        urls->setPlainText(server.url("/stations.txt").toString() + u'\n' + server.url("/weather.txt").toString());
        QSignalSpy done(f.window->elementSets(), &slew::sky::ElementSetSources::finished);
        QTest::mouseClick(dialog->findChild<QPushButton *>(QStringLiteral("elementSetRefresh")), Qt::LeftButton);
        QVERIFY(done.count() > 0 || done.wait(20000));
        QCOMPARE(server.requests, 2);

        auto *status = dialog->findChild<QTreeWidget *>(QStringLiteral("elementSetStatus"));
        QCOMPARE(status->topLevelItemCount(), 2);
        for (int i = 0; i < 2; ++i) {
            QCOMPARE(status->topLevelItem(i)->text(1), QStringLiteral("fetched"));
            QCOMPARE(status->topLevelItem(i)->text(2), QStringLiteral("1"));
            QCOMPARE(status->topLevelItem(i)->childCount(), 1);
        }
        // Each set's own age, under its source.
        QTreeWidgetItem *iss = status->topLevelItem(0)->child(0);
        QCOMPARE(iss->text(0), QStringLiteral("ISS (ZARYA)"));
        QCOMPARE(iss->text(2), QStringLiteral("25544"));
        QCOMPARE(iss->text(3), QStringLiteral("2.0 days"));
        QVERIFY(status->topLevelItem(1)->child(0)->text(1).startsWith(QStringLiteral("2018-01-20")));

        // A week's limit names only the 2018 set; a day's names both.
        auto *warning = dialog->findChild<QLabel *>(QStringLiteral("elementSetStaleWarning"));
        auto *limit = dialog->findChild<QDoubleSpinBox *>(QStringLiteral("elementSetAgeLimit"));
        limit->setValue(7.0);
        QVERIFY2(warning->text().startsWith(QStringLiteral("1 element set older")), qPrintable(warning->text()));
        QVERIFY(warning->text().contains(QStringLiteral("NOAA 19")));
        QVERIFY(!warning->text().contains(QStringLiteral("ISS")));
        limit->setValue(1.0);
        QVERIFY2(warning->text().startsWith(QStringLiteral("2 element sets older")), qPrintable(warning->text()));
        QCOMPARE(slew::ui::ElementSetsDialog::savedAgeLimitDays(), 1.0);
        // One limit: the station tracks (and schedules) by the same one.
        QCOMPARE(f.window->station()->elementAgeLimitDays(), 1.0);
        limit->setValue(7.0);
        QCOMPARE(f.window->station()->elementAgeLimitDays(), 7.0);

        // The next start: the same sources from the cache, the server gone,
        // read off the event loop while the window is already up.
        server.close();
        WindowFixture next;
        QCOMPARE(next.window->elementSets()->urls().size(), 2);
        QCOMPARE(next.window->station()->elementAgeLimitDays(), 7.0); // the saved limit
        // A hand-edited limit the dialog would not allow is not taken.
        for (const char *bad : {"1e9", "0.1", "nan", "-3"}) {
            QSettings().setValue(QStringLiteral("sky/elementSetAgeLimitDays"), QString::fromLatin1(bad));
            QCOMPARE(slew::ui::ElementSetsDialog::savedAgeLimitDays(), 14.0);
        }
        QSettings().setValue(QStringLiteral("sky/elementSetAgeLimitDays"), 7.0);
        QTRY_COMPARE(next.window->elementSets()->sets().size(), 2);
        QVERIFY(next.window->elementSets()->status()[0].fromCache);
        QCOMPARE(server.requests, 2);
    }

    // A full copy, then a server that answers with a page holding one set:
    // the full copy stays, and the dialog and the log say why.
    void aOneSetPageKeepsTheFullCopyAndSaysWhy()
    {
        TinyHttpServer server;
        QVERIFY(server.listen(QHostAddress::LocalHost, 0));
        QFile full(QStringLiteral(SLEW_TEST_DATA_DIR "/gpredict-satellites-2018.tle"));
        QVERIFY(full.open(QIODevice::ReadOnly));
        server.pages.insert("/amateur.txt", full.readAll());

        WindowFixture f;
        auto *dialog = openDialog(f);
        dialog->findChild<QPlainTextEdit *>(QStringLiteral("elementSetUrls"))->setPlainText(server.url("/amateur.txt").toString());
        QSignalSpy done(f.window->elementSets(), &slew::sky::ElementSetSources::finished);
        QVERIFY(dialog->refresh());
        QVERIFY(done.wait(20000));
        auto *status = dialog->findChild<QTreeWidget *>(QStringLiteral("elementSetStatus"));
        QCOMPARE(status->topLevelItem(0)->text(2), QStringLiteral("979"));

        server.pages.insert("/amateur.txt", "<html><body><pre>\n" + kNoaa2018 + "</pre></body></html>\n");
        QVERIFY(dialog->refresh());
        QVERIFY(done.wait(20000));
        const QString state = status->topLevelItem(0)->text(1);
        QVERIFY2(state.startsWith(QStringLiteral("from the cache: the answer is an HTML page")), qPrintable(state));
        QCOMPARE(status->topLevelItem(0)->text(2), QStringLiteral("979"));
        const QString message = dialog->findChild<QLabel *>(QStringLiteral("elementSetMessage"))->text();
        QVERIFY2(message.contains(QStringLiteral("1 source not refreshed")), qPrintable(message));
        QCOMPARE(f.window->elementSets()->sets().size(), 979);
    }

    void aLineThatIsNotAUrlIsRefusedByNumber()
    {
        WindowFixture f;
        auto *dialog = openDialog(f);
        auto *urls = dialog->findChild<QPlainTextEdit *>(QStringLiteral("elementSetUrls"));
        const QList<QUrl> before = f.window->elementSets()->urls();
        urls->setPlainText(QStringLiteral("http://127.0.0.1:1/a.txt\n\nceles trak dot org"));
        QVERIFY(!dialog->refresh());
        const QString message = dialog->findChild<QLabel *>(QStringLiteral("elementSetMessage"))->text();
        QVERIFY2(message.contains(QStringLiteral("Line 3")), qPrintable(message));
        QCOMPARE(f.window->elementSets()->urls(), before); // nothing taken, nothing fetched
        QVERIFY(!f.window->elementSets()->isRefreshing());
    }

    void aLocalFileIsASource()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("amateur.txt"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(kNoaa2018 + "NOT A SET\n1 broken\n");
        file.close();

        WindowFixture f;
        auto *dialog = openDialog(f);
        dialog->findChild<QPlainTextEdit *>(QStringLiteral("elementSetUrls"))->clear();
        // Its sets at once, without a Refresh (and without the network).
        QSignalSpy read(f.window->elementSets(), &slew::sky::ElementSetSources::loaded);
        dialog->addFile(path);
        QVERIFY(read.count() > 0 || read.wait(20000));
        QCOMPARE(f.window->elementSets()->sets().size(), 1);
        QCOMPARE(f.window->elementSets()->urls(), QList<QUrl>{QUrl::fromLocalFile(path)});
        QSignalSpy done(f.window->elementSets(), &slew::sky::ElementSetSources::finished);
        QVERIFY(dialog->refresh());
        QVERIFY(done.count() > 0 || done.wait(20000));
        auto *source = dialog->findChild<QTreeWidget *>(QStringLiteral("elementSetStatus"))->topLevelItem(0);
        QCOMPARE(source->text(0), QUrl::fromLocalFile(path).toString());
        QCOMPARE(source->text(1), QStringLiteral("fetched"));
        QCOMPARE(source->text(2), QStringLiteral("1"));
        QVERIFY(source->text(4).toInt() >= 1); // the broken lines, refused by number
        QVERIFY2(source->toolTip(4).contains(QStringLiteral("line ")), qPrintable(source->toolTip(4)));
    }
};

QTEST_MAIN(TestElementSets)
#include "tst_elementsets.moc"
