// ComediDaq without a card: the failure path (there is no Comedi hardware or kernel
// driver where the tests run).
#ifdef PADROB_HAVE_COMEDI

#include "trainer/input/comedi_daq.h"

#include <QTemporaryDir>
#include <QFile>

#include <gtest/gtest.h>

#include <utility>
#include <vector>

using trainer::ComediDaq;
using trainer::DeviceStatus;

TEST(ComediDaq, MissingDeviceFileFailsWithAHintAndIsRetried)
{
    const QString file = "/nonexistent/comedi7";
    ComediDaq d(file);
    EXPECT_EQ(d.info().id, "comedi:" + file);
    EXPECT_EQ(d.info().kind, trainer::DeviceKind::Comedi);
    EXPECT_TRUE(d.info().name.contains(file));
    EXPECT_TRUE(d.info().axes.isEmpty());
    EXPECT_EQ(d.status(), DeviceStatus::Failed);
    EXPECT_FALSE(d.isOpen());
    const QString text = d.statusText();
    EXPECT_TRUE(text.contains(file)) << text.toStdString();
    EXPECT_TRUE(text.contains("comedi_config")) << text.toStdString();
    EXPECT_TRUE(text.contains("No such file")) << text.toStdString();  // comedi_strerror's words
    EXPECT_EQ(d.openAttempts(), 1u);

    // every 2 s of station time, from the first poll on
    const std::vector<std::pair<double, std::uint64_t>> polls = {
        {100.0, 1}, {101.0, 1}, {102.0, 2}, {103.9, 2}, {104.0, 3}, {110.0, 4}};
    for (const auto& [t, attempts] : polls) {
        d.poll(t);
        EXPECT_EQ(d.openAttempts(), attempts) << "at " << t;
        EXPECT_EQ(d.status(), DeviceStatus::Failed);
        EXPECT_TRUE(d.statusText().contains(file));
    }
    EXPECT_EQ(d.sample().count, 0u);
    EXPECT_EQ(d.infoVersion(), 0u);
}

TEST(ComediDaq, AFileThatIsNoCardFails)
{
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString file = dir.filePath("comedi0");
    QFile f(file);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write("not a card");
    f.close();
    ComediDaq d(file);
    EXPECT_EQ(d.status(), DeviceStatus::Failed);
    EXPECT_TRUE(d.statusText().contains(file)) << d.statusText().toStdString();
    d.poll(0.0);
    d.poll(2.0);
    EXPECT_EQ(d.openAttempts(), 2u);
    EXPECT_EQ(d.status(), DeviceStatus::Failed);
}

#endif  // PADROB_HAVE_COMEDI
