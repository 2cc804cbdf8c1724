// SPDX-License-Identifier: GPL-3.0-or-later
// Sky → Station…: the text is checked as it is typed, OK is disabled while
// it is wrong, and an accepted station is kept in the settings, or the
// dialog stays open saying why it could not be.

#include "tracking/stationdialog.h"

#include <QDialogButtonBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

using slew::ui::StationDialog;

class TestStationDialog : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("SlewTest"));
        QCoreApplication::setApplicationName(QStringLiteral("tst_stationdialog"));
        QSettings().clear();
    }

    void checksAsYouTypeAndSaves_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<bool>("ok");
        QTest::addColumn<QString>("feedback");
        QTest::newRow("locator") << QStringLiteral("JO65hq") << true << QStringLiteral("55.6875° N");
        QTest::newRow("coordinates") << QStringLiteral("-33.9,18.4,120") << true << QStringLiteral("locator JF96");
        QTest::newRow("bad locator") << QStringLiteral("ZZ99") << false << QStringLiteral("letters A to R");
        QTest::newRow("latitude") << QStringLiteral("95,10") << false << QStringLiteral("latitude");
        QTest::newRow("empty") << QString() << false << QStringLiteral("no station");
    }

    void checksAsYouTypeAndSaves()
    {
        QFETCH(QString, text);
        QFETCH(bool, ok);
        QFETCH(QString, feedback);
        StationDialog dialog;
        auto *edit = dialog.findChild<QLineEdit *>(QStringLiteral("stationEdit"));
        auto *label = dialog.findChild<QLabel *>(QStringLiteral("stationFeedback"));
        auto *okButton = dialog.findChild<QDialogButtonBox *>()->button(QDialogButtonBox::Ok);
        QVERIFY(edit && label && okButton);
        edit->clear();
        QTest::keyClicks(edit, text);
        QCOMPARE(okButton->isEnabled(), ok);
        QVERIFY2(label->text().contains(feedback), qPrintable(label->text()));
        if (!ok)
            return;
        okButton->click();
        QCOMPARE(dialog.result(), int(QDialog::Accepted));
        slew::sky::Site saved;
        QString savedText;
        QVERIFY(StationDialog::savedStation(&saved, &savedText));
        QCOMPARE(savedText, text);
        QCOMPARE(saved.latitudeDeg, dialog.station().latitudeDeg);
        // A new dialog starts from the saved station.
        StationDialog again;
        QCOMPARE(again.findChild<QLineEdit *>(QStringLiteral("stationEdit"))->text(), text);
    }

    // Settings that cannot be written (here a file where their directory
    // goes): OK leaves the dialog open saying so, naming the file, instead
    // of closing as if the station were kept. Last: it moves the settings.
    void aStationThatCannotBeSavedIsSaidSo()
    {
        QTemporaryDir dir;
        QFile notADirectory(dir.filePath(QStringLiteral("config")));
        QVERIFY(notADirectory.open(QIODevice::WriteOnly));
        notADirectory.close();
        QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, notADirectory.fileName());
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, notADirectory.fileName());
        StationDialog dialog;
        dialog.show();
        auto *edit = dialog.findChild<QLineEdit *>(QStringLiteral("stationEdit"));
        auto *label = dialog.findChild<QLabel *>(QStringLiteral("stationFeedback"));
        edit->setText(QStringLiteral("FN31pr"));
        dialog.findChild<QDialogButtonBox *>()->button(QDialogButtonBox::Ok)->click();
        QVERIFY(dialog.isVisible());
        QCOMPARE(dialog.result(), int(QDialog::Rejected));
        QVERIFY2(label->text().contains(QStringLiteral("not saved")) && label->text().contains(QSettings().fileName()),
                 qPrintable(label->text()));
    }
};

QTEST_MAIN(TestStationDialog)
#include "tst_stationdialog.moc"
