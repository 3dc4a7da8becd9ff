#include "trainer/input/daq_protocol.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

using namespace trainer::daq;

namespace {

std::string ident8(int rate = 100, std::string name = "Test console")
{
    return identificationLine({kProtocolVersion, 8, 10, rate, std::move(name)});
}

std::string sample8(std::uint16_t seq, std::uint16_t base = 0)
{
    std::vector<std::uint16_t> v;
    for (int i = 0; i < 8; ++i)
        v.push_back(std::uint16_t(base + i));
    return sampleLine(seq, v);
}

// a well-formed 8-channel stream of n samples, seq 0…n−1
std::string stream8(int n)
{
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> value(0, 1023);
    std::string s;
    for (int k = 0; k < n; ++k) {
        std::vector<std::uint16_t> v;
        for (int i = 0; i < 8; ++i)
            v.push_back(std::uint16_t(value(rng)));
        s += sampleLine(std::uint16_t(k), v);
    }
    return s;
}

}  // namespace

TEST(DaqProtocol, Crc8CheckValue)
{
    EXPECT_EQ(crc8("123456789"), 0xF4);
    EXPECT_EQ(crc8(""), 0x00);
    // the checksum of a line's body is its own CC
    const std::string line = sampleLine(1, std::vector<std::uint16_t>{512});
    EXPECT_EQ(line.substr(0, 7), "$1,512*");
    EXPECT_EQ(std::stoi(line.substr(7, 2), nullptr, 16), crc8("1,512"));
}

TEST(DaqProtocol, BuildersWriteTheDocumentedLines)
{
    const std::string s = sampleLine(65535, std::vector<std::uint16_t>{0, 1023, 65535});
    EXPECT_EQ(s.substr(0, s.size() - 3), "$65535,0,1023,65535*");
    EXPECT_EQ(s.back(), '\n');
    // uppercase hex
    for (char c : s.substr(s.size() - 3, 2))
        EXPECT_TRUE((c >= '0' && c <= '9') || (c >= 'A' && c <= 'F')) << c;

    EXPECT_EQ(identificationLine({1, 8, 10, 100, "Lever console"}).substr(0, 40),
              "#PADROB-DAQ,1,8,10,100,Lever console*" + framedLine('#', "PADROB-DAQ,1,8,10,100,Lever console").substr(37, 3));
    EXPECT_EQ(identificationLine({1, 4, 12, 50, ""}), framedLine('#', "PADROB-DAQ,1,4,12,50"));
    EXPECT_EQ(identificationRequest(), "?\n");
    EXPECT_EQ(rateCommand(250), "R250\n");

    EXPECT_THROW(sampleLine(0, std::vector<std::uint16_t>{}), std::invalid_argument);
    EXPECT_THROW(sampleLine(0, std::vector<std::uint16_t>(17, 0)), std::invalid_argument);
    EXPECT_THROW(identificationLine({1, 0, 10, 100, ""}), std::invalid_argument);
    EXPECT_THROW(identificationLine({1, 8, 10, 100, "a,b"}), std::invalid_argument);
    EXPECT_THROW(identificationLine({1, 8, 10, 100, "a*b"}), std::invalid_argument);
    EXPECT_THROW(identificationLine({1, 8, 17, 100, ""}), std::invalid_argument);
    EXPECT_THROW(rateCommand(0), std::invalid_argument);
    EXPECT_THROW(rateCommand(1001), std::invalid_argument);
}

TEST(DaqProtocol, RoundTrip)
{
    Parser p;
    EXPECT_EQ(p.channels(), 0);
    EXPECT_EQ(p.feed(ident8(200, "Bench box")), 0u);
    ASSERT_TRUE(p.identification());
    EXPECT_EQ(*p.identification(), (Identification{1, 8, 10, 200, "Bench box"}));
    EXPECT_EQ(p.channels(), 8);

    EXPECT_EQ(p.feed(sample8(0, 100) + sample8(1, 500)), 2u);
    EXPECT_EQ(p.latest().seq, 1);
    EXPECT_EQ(p.latest().channels, 8);
    for (int i = 0; i < 8; ++i)
        EXPECT_EQ(p.latest().values[std::size_t(i)], 500 + i);
    const std::vector<std::uint16_t> extremes{0, 65535, 1, 65534, 7, 8, 9, 10};
    EXPECT_EQ(p.feed(sampleLine(2, extremes)), 1u);
    for (std::size_t i = 0; i < extremes.size(); ++i)
        EXPECT_EQ(p.latest().values[i], extremes[i]);

    const Stats& st = p.stats();
    EXPECT_EQ(st.goodLines, 3u);
    EXPECT_EQ(st.identLines, 1u);
    EXPECT_EQ(st.droppedLines(), 0u);
    EXPECT_EQ(st.garbageLines, 0u);
    EXPECT_EQ(st.lostSamples, 0u);

    // sixteen channels, leading zeros, a lowercase checksum
    Parser q;
    EXPECT_EQ(q.feed(sampleLine(9, std::vector<std::uint16_t>(16, 4095))), 1u);
    EXPECT_EQ(q.channels(), 16);
    std::string lower = framedLine('$', "00012,0042");
    for (char& c : lower)
        if (c >= 'A' && c <= 'F')
            c = char(c - 'A' + 'a');
    EXPECT_EQ(q.feed(lower), 0u);  // one value, not sixteen
    EXPECT_EQ(q.stats().wrongChannels, 1u);
    Parser r;
    EXPECT_EQ(r.feed(lower), 1u);
    EXPECT_EQ(r.latest().seq, 12);
    EXPECT_EQ(r.latest().values[0], 42);
}

TEST(DaqProtocol, BadLinesAreDroppedForTheirReason)
{
    enum Reason { Checksum, Syntax, Channels };
    const std::string good = sample8(3);
    std::string flippedDigit = good;
    flippedDigit[1] = '4';  // seq 3 → 4, checksum of seq 3
    std::string badCrc = good;
    badCrc[good.size() - 2] = badCrc[good.size() - 2] == '0' ? '1' : '0';

    const std::vector<std::pair<std::string, Reason>> cases = {
        {flippedDigit, Checksum},
        {badCrc, Checksum},
        {good.substr(0, good.size() - 4) + "\n", Syntax},         // truncated: no "*CC"
        {good.substr(0, good.size() - 2) + "\n", Syntax},         // "*C"
        {good.substr(0, good.size() - 3) + "G0\n", Syntax},       // not hex
        {"$\n", Syntax},
        {"$*00\n", Syntax},
        {framedLine('$', ""), Syntax},
        {framedLine('$', "5"), Syntax},                           // a seq and no values
        {framedLine('$', "5,1,,3,4,5,6,7,8"), Syntax},            // empty field
        {framedLine('$', "5,1,2,3,4,5,6,7,65536"), Syntax},       // value out of range
        {framedLine('$', "65536,1,2,3,4,5,6,7,8"), Syntax},       // seq out of range
        {framedLine('$', "5,1,2,3,4,5,6,7,000008"), Syntax},      // six digits
        {framedLine('$', "5,1,2,3,4,5,6,7,-8"), Syntax},
        {framedLine('$', "5,1,2,3,4,5,6,7,+8"), Syntax},
        {framedLine('$', "5,1,2,3,4,5,6,7, 8"), Syntax},
        {framedLine('$', "5,1,2,3,4,5,6,7,8,"), Syntax},          // trailing comma
        {framedLine('$', "5,1,2,3,4,5,6,7,8\r"), Syntax},         // a CR inside
        {framedLine('$', "5,1,2,3,4,5,6,7,0x8"), Syntax},
        {framedLine('$', "5,1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17"), Syntax},  // 17 values
        {framedLine('#', "PADROB-DAQ,2,8,10,100"), Syntax},      // unknown version
        {framedLine('#', "PADROB-DAX,1,8,10,100"), Syntax},
        {framedLine('#', "PADROB-DAQ,1,17,10,100"), Syntax},
        {framedLine('#', "PADROB-DAQ,1,8,0,100"), Syntax},
        {framedLine('#', "PADROB-DAQ,1,8,10,1001"), Syntax},
        {framedLine('#', "PADROB-DAQ,1,8,10,0"), Syntax},
        {framedLine('#', "PADROB-DAQ,1,8,10"), Syntax},
        {framedLine('#', "PADROB-DAQ,1,8,10,100,a,b"), Syntax},  // a ',' in the name
        {framedLine('#', "PADROB-DAQ,1,8,10,100,caf\xC3\xA9"), Syntax},  // not ASCII
        {sampleLine(5, std::vector<std::uint16_t>{1, 2, 3}), Channels},
        {sampleLine(5, std::vector<std::uint16_t>(16, 1)), Channels},
    };
    for (const auto& [line, reason] : cases) {
        Parser p;
        p.feed(ident8());
        EXPECT_EQ(p.feed(line + good), 1u) << line;  // the good line after it still arrives
        const Stats& st = p.stats();
        EXPECT_EQ(st.badChecksum, reason == Checksum ? 1u : 0u) << line;
        EXPECT_EQ(st.badSyntax, reason == Syntax ? 1u : 0u) << line;
        EXPECT_EQ(st.wrongChannels, reason == Channels ? 1u : 0u) << line;
        EXPECT_EQ(st.droppedLines(), 1u) << line;
        EXPECT_EQ(st.goodLines, 1u) << line;
        EXPECT_EQ(p.latest().seq, 3) << line;
        EXPECT_EQ(p.identification()->channels, 8) << line;
    }
}

TEST(DaqProtocol, ChannelCountFromIdentificationOrFirstLine)
{
    // before any identification the first good line sets it
    Parser p;
    EXPECT_EQ(p.feed(sampleLine(0, std::vector<std::uint16_t>{1, 2, 3})), 1u);
    EXPECT_EQ(p.channels(), 3);
    EXPECT_EQ(p.feed(sample8(1)), 0u);
    EXPECT_EQ(p.stats().wrongChannels, 1u);
    // an identification overrides it
    p.feed(ident8());
    EXPECT_EQ(p.channels(), 8);
    EXPECT_EQ(p.feed(sample8(2)), 1u);
    EXPECT_EQ(p.feed(sampleLine(3, std::vector<std::uint16_t>{1, 2, 3})), 0u);
    EXPECT_EQ(p.stats().wrongChannels, 2u);
    // and a later identification overrides the earlier one
    p.feed(identificationLine({1, 2, 12, 50, ""}));
    EXPECT_EQ(p.channels(), 2);
    EXPECT_EQ(p.identification()->bits, 12);
    EXPECT_EQ(p.identification()->name, "");
    EXPECT_EQ(p.feed(sampleLine(0, std::vector<std::uint16_t>{4000, 5})), 1u);
}

TEST(DaqProtocol, LongLinesAreSkippedToTheNextNewline)
{
    // the longest line: 256 bytes from '#' to the checksum
    const std::string head = "#PADROB-DAQ,1,8,10,100,";
    const std::size_t nameRoom = kMaxLineLength - head.size() - 3;
    const std::string longest = identificationLine({1, 8, 10, 100, std::string(nameRoom, 'n')});
    ASSERT_EQ(longest.size(), kMaxLineLength + 1);
    Parser p;
    p.feed(longest);
    EXPECT_EQ(p.stats().identLines, 1u);
    std::string crlf = longest;
    crlf.insert(crlf.size() - 1, "\r");
    p.feed(crlf);
    EXPECT_EQ(p.stats().identLines, 2u);
    EXPECT_EQ(p.stats().tooLong, 0u);

    // one byte more
    p.feed(identificationLine({1, 8, 10, 100, std::string(nameRoom + 1, 'n')}));
    EXPECT_EQ(p.stats().tooLong, 1u);
    EXPECT_EQ(p.stats().identLines, 2u);

    // a flood without newlines, markers included, then a good line
    std::string flood = "$1,2,3";
    for (int i = 0; i < 10000; ++i)
        flood += i % 100 == 50 ? "$#" : "1234567890";  // markers only once it is too long
    EXPECT_EQ(p.feed(flood), 0u);
    EXPECT_LE(p.bufferedBytes(), kMaxLineLength + 1);
    EXPECT_EQ(p.feed("\n" + sample8(7)), 1u);
    EXPECT_EQ(p.stats().tooLong, 2u);
    EXPECT_EQ(p.stats().badSyntax, 0u);
    EXPECT_EQ(p.latest().seq, 7);
}

TEST(DaqProtocol, GarbageBeforeAMarkerIsCountedOncePerLine)
{
    Parser p;
    p.feed(ident8());
    EXPECT_EQ(p.feed("xyz" + sample8(1)), 1u);  // bytes before '$': the line still counts
    EXPECT_EQ(p.stats().garbageLines, 1u);
    EXPECT_EQ(p.feed("Hello from the bootloader\r\n"), 0u);  // no marker at all
    EXPECT_EQ(p.stats().garbageLines, 2u);
    EXPECT_EQ(p.feed("\n\r\n\n"), 0u);  // blank lines are nothing
    EXPECT_EQ(p.stats().garbageLines, 2u);
    EXPECT_EQ(p.stats().droppedLines(), 0u);

    // a line cut short by the next marker (a reset mid-line) is a syntax drop
    const std::string cut = sample8(2).substr(0, 10);
    EXPECT_EQ(p.feed(cut + sample8(3)), 1u);
    EXPECT_EQ(p.stats().badSyntax, 1u);
    EXPECT_EQ(p.latest().seq, 3);
    EXPECT_EQ(p.stats().lostSamples, 1u);  // seq 2
}

TEST(DaqProtocol, SeqWrapIsNotAGapAndJumpsCountLostSamples)
{
    Parser p;
    p.feed(ident8());
    p.feed(sample8(65534) + sample8(65535) + sample8(0) + sample8(1));
    EXPECT_EQ(p.stats().goodLines, 4u);
    EXPECT_EQ(p.stats().lostSamples, 0u);
    p.feed(sample8(5));  // 2, 3, 4 missing
    EXPECT_EQ(p.stats().lostSamples, 3u);
    p.feed(sample8(65533) + sample8(2));  // 6…65532, then 65534, 65535, 0, 1
    EXPECT_EQ(p.stats().lostSamples, 3u + (65533 - 6) + 4);

    // an identification restarts the sequence (the box was reset)
    Parser q;
    q.feed(ident8() + sample8(100) + ident8() + sample8(0) + sample8(1));
    EXPECT_EQ(q.stats().lostSamples, 0u);
    // so does a reopened stream
    q.resetStream();
    q.feed(sample8(50));
    EXPECT_EQ(q.stats().lostSamples, 0u);
    q.feed(sample8(52));
    EXPECT_EQ(q.stats().lostSamples, 1u);
}

TEST(DaqProtocol, SplitLinesFedByteByByte)
{
    const std::string s = ident8() + sample8(0, 10) + "junk\n" + sample8(1, 20) + sample8(2, 30);
    Parser p;
    std::size_t samples = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const std::size_t n = p.feed(std::string_view(&s[i], 1));
        if (n > 0) {
            EXPECT_EQ(s[i], '\n');  // a line completes at its newline, not before
        }
        samples += n;
    }
    EXPECT_EQ(samples, 3u);
    EXPECT_EQ(p.stats().identLines, 1u);
    EXPECT_EQ(p.stats().garbageLines, 1u);
    EXPECT_EQ(p.latest().seq, 2);
    EXPECT_EQ(p.latest().values[0], 30);
    EXPECT_EQ(p.bufferedBytes(), 0u);

    // partial line held between feeds
    Parser q;
    const std::string line = sample8(9);
    EXPECT_EQ(q.feed(line.substr(0, 12)), 0u);
    EXPECT_EQ(q.bufferedBytes(), 12u);
    EXPECT_EQ(q.feed(line.substr(12)), 1u);
    // resetStream forgets the partial line
    q.feed(line.substr(0, 12));
    q.resetStream();
    EXPECT_EQ(q.feed(line.substr(12)), 0u);
    EXPECT_EQ(q.stats().garbageLines, 1u);
}

TEST(DaqProtocol, CrLfLineEnds)
{
    auto crlf = [](std::string line) {
        line.insert(line.size() - 1, "\r");
        return line;
    };
    Parser p;
    EXPECT_EQ(p.feed(crlf(ident8()) + crlf(sample8(0)) + crlf(sample8(1))), 2u);
    EXPECT_EQ(p.stats().identLines, 1u);
    EXPECT_EQ(p.stats().droppedLines(), 0u);
    EXPECT_EQ(p.stats().garbageLines, 0u);
    // a lone CR is not a line end, two are not accepted
    std::string twoCr = crlf(crlf(sample8(2)));
    EXPECT_EQ(p.feed(twoCr), 0u);
    EXPECT_EQ(p.stats().badSyntax, 1u);
}

TEST(DaqProtocol, RandomBytesGiveNoSamplesAndBoundedMemory)
{
    std::mt19937 rng(20240611);
    std::uniform_int_distribution<int> byte(0, 255);
    std::uniform_int_distribution<int> chunk(1, 700);
    Parser p;
    std::size_t total = 0, samples = 0;
    while (total < 400 * 1024) {
        std::string s(std::size_t(chunk(rng)), '\0');
        for (char& c : s)
            c = char(byte(rng));
        samples += p.feed(s);
        total += s.size();
        ASSERT_LE(p.bufferedBytes(), kMaxLineLength + 1);
    }
    // a random line needs '$' or '#', only digits and commas, "*CC" and a matching CRC
    EXPECT_LE(samples, 1u);
    EXPECT_LE(p.stats().identLines, 0u);
    EXPECT_GT(p.stats().garbageLines + p.stats().droppedLines(), 100u);

    // and a good stream right after it is read
    EXPECT_EQ(p.feed("\n" + ident8() + stream8(50)), 50u);
}

TEST(DaqProtocol, ProtocolLikeJunkOnlyPassesByChecksumAccident)
{
    // junk lines shaped like the protocol's (marker, digits and commas, "*", two hex
    // digits): many are well formed, and only about 1 in 256 can have a matching CRC
    const std::string body = "0123456789,,,";
    const std::string hex = "0123456789ABCDEF";
    std::mt19937 rng(99);
    std::uniform_int_distribution<std::size_t> length(1, 40);
    std::uniform_int_distribution<std::size_t> pickBody(0, body.size() - 1);
    std::uniform_int_distribution<std::size_t> pickHex(0, hex.size() - 1);
    std::bernoulli_distribution ident(0.1);
    std::string s;
    while (s.size() < 300 * 1024) {
        s += ident(rng) ? "#PADROB-DAQ," : "$";
        for (std::size_t i = length(rng); i > 0; --i)
            s += body[pickBody(rng)];
        s += '*';
        s += hex[pickHex(rng)];
        s += hex[pickHex(rng)];
        s += '\n';
    }
    Parser p;
    const std::size_t samples = p.feed(s);
    const Stats& st = p.stats();
    EXPECT_GT(st.badChecksum, 10000u);
    // accepted or dropped only after the checksum matched: about badChecksum / 255
    const std::uint64_t crcMatched = samples + st.identLines + st.wrongChannels + st.badSyntax;
    EXPECT_LE(crcMatched, st.badChecksum / 128);
    EXPECT_LE(p.bufferedBytes(), kMaxLineLength + 1);
}

TEST(DaqProtocol, SingleBitErrorsNeverGiveAWrongSample)
{
    // CRC-8 catches every single-bit error inside a line; a flip that creates a marker
    // leaves a tail with too few values, dropped by the channel count
    const int n = 5000;
    std::map<int, std::vector<std::uint16_t>> sent;
    std::mt19937 rng(5);
    std::uniform_int_distribution<int> value(0, 1023);
    std::uniform_int_distribution<int> bit(0, 7);
    std::bernoulli_distribution corrupt(0.2);
    std::string s = ident8();
    int flipped = 0;
    for (int k = 0; k < n; ++k) {
        std::vector<std::uint16_t> v;
        for (int i = 0; i < 8; ++i)
            v.push_back(std::uint16_t(value(rng)));
        sent[k] = v;
        std::string line = sampleLine(std::uint16_t(k), v);
        // one flipped bit in a line at most; the first and last lines are intact
        if (k > 0 && k < n - 1 && corrupt(rng)) {
            std::uniform_int_distribution<std::size_t> where(0, line.size() - 1);
            line[where(rng)] ^= char(1 << bit(rng));
            ++flipped;
        }
        s += line;
    }
    ASSERT_GT(flipped, 900);

    Parser p;
    std::uniform_int_distribution<std::size_t> chunk(1, 64);
    std::size_t wrong = 0;
    for (std::size_t at = 0; at < s.size();) {
        // feed up to each newline so that every accepted line can be checked
        std::size_t end = std::min(s.size(), at + chunk(rng));
        const std::size_t nl = s.find('\n', at);
        if (nl != std::string::npos && nl < end)
            end = nl + 1;
        if (p.feed(std::string_view(s).substr(at, end - at)) > 0) {
            const Sample& got = p.latest();
            const auto it = sent.find(got.seq);
            if (it == sent.end()
                || !std::equal(it->second.begin(), it->second.end(), got.values.begin()))
                ++wrong;
        }
        at = end;
    }
    EXPECT_EQ(wrong, 0u);
    EXPECT_GT(p.stats().droppedLines(), std::uint64_t(flipped) * 9 / 10);
    EXPECT_EQ(p.stats().goodLines + p.stats().lostSamples, std::uint64_t(n));
    EXPECT_EQ(p.latest().seq, n - 1);
}
