#pragma once
// The Padrob DAQ line protocol (docs/daq-protocol.md): what a console box of valve
// levers sends over a serial port and what the host answers. Pure C++, no Qt and no
// I/O: a checksum, line builders (for tests, tools and the docs' examples) and an
// incremental parser that takes the byte stream in chunks of any size.
//
// Device → host, ASCII lines ending in "\n" (an optional "\r" before it is accepted):
//   `$<seq>,<v1>,…,<vN>*<CC>`                          a sample
//   `#PADROB-DAQ,<version>,<channels>,<bits>,<rate>[,<name>]*<CC>`   the identification
// seq 0…65535 (wraps to 0), N = 1…16 values 0…65535, CC two hex digits of CRC-8/SMBUS
// over the bytes strictly between the marker ('$' or '#') and '*'.
// Host → device: "?\n" (send the identification), "R<hz>\n" (sample rate 1…1000).
//
// The parser holds at most one line (≤ 257 bytes), allocates only to keep an
// identification's name, and never produces a sample from a line that is not well
// formed with a matching checksum; everything else is dropped and counted in Stats.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace trainer::daq {

inline constexpr int kProtocolVersion = 1;
inline constexpr int kMaxChannels = 16;
inline constexpr int kMinRate = 1;     ///< [Hz] lowest rate "R" accepts
inline constexpr int kMaxRate = 1000;  ///< [Hz] highest rate "R" accepts
/// Longest line: from the marker to the checksum's last digit, without "\r\n" [bytes].
inline constexpr std::size_t kMaxLineLength = 256;
inline constexpr std::string_view kIdentificationTag = "PADROB-DAQ";

/// CRC-8/SMBUS: polynomial 0x07, init 0x00, not reflected, no final xor. The check
/// value (CRC of "123456789") is 0xF4.
std::uint8_t crc8(std::string_view bytes);

/// What a box says about itself.
struct Identification {
    int version = kProtocolVersion;
    int channels = 0;   ///< 1…16
    int bits = 10;      ///< ADC resolution, 1…16: readings are 0…2^bits − 1
    int rate = 100;     ///< [Hz] sample lines per second, 1…1000
    std::string name;   ///< printable ASCII without ',' '*' '$' '#'; may be empty

    bool operator==(const Identification&) const = default;
};

/// `marker + body + '*' + CC + "\n"` with CC the uppercase hex CRC of body. Builds
/// any line, well formed or not (tests craft bad bodies with a good checksum).
std::string framedLine(char marker, std::string_view body);
/// A sample line, e.g. sampleLine(7, {512, 1023}) == "$7,512,1023*XX\n".
/// Throws std::invalid_argument unless 1…16 values are given.
std::string sampleLine(std::uint16_t seq, std::span<const std::uint16_t> values);
/// The identification line. Throws std::invalid_argument when a field is out of range
/// or the name has a forbidden character.
std::string identificationLine(const Identification& id);
/// Host → device: ask for the identification ("?\n").
std::string identificationRequest();
/// Host → device: set the sample rate ("R<hz>\n"). Throws std::invalid_argument
/// outside kMinRate…kMaxRate.
std::string rateCommand(int hz);

/// A good sample line.
struct Sample {
    std::uint16_t seq = 0;
    int channels = 0;                                ///< values in use
    std::array<std::uint16_t, kMaxChannels> values{};  ///< raw readings, first `channels` valid
};

/// Counters since construction (or reset()).
struct Stats {
    std::uint64_t goodLines = 0;          ///< sample lines accepted
    std::uint64_t identLines = 0;         ///< identification lines accepted
    std::uint64_t badChecksum = 0;        ///< CRC mismatch
    /// Malformed: no or bad "*CC", bad or out-of-range number, wrong field count,
    /// unknown tag or protocol version, a '\r' inside, a line cut short by the next
    /// '$' or '#' before its "\n".
    std::uint64_t badSyntax = 0;
    std::uint64_t wrongChannels = 0;      ///< value count differs from the expected one
    std::uint64_t tooLong = 0;            ///< longer than kMaxLineLength (skipped to "\n")
    /// Lines with bytes before their marker, or with no marker at all (each counted
    /// once; a blank line is not counted). Not dropped lines: they may still hold one.
    std::uint64_t garbageLines = 0;
    /// Samples missing from the seq sequence (gaps modulo 65536), dropped lines included.
    std::uint64_t lostSamples = 0;

    /// Lines dropped for any reason (checksum, syntax, channels, too long).
    std::uint64_t droppedLines() const { return badChecksum + badSyntax + wrongChannels + tooLong; }
};

/// Incremental parser of the device → host stream.
class Parser {
public:
    Parser();

    /// Takes the next bytes of the stream (any split, any content). Returns the number
    /// of good sample lines among the lines completed by them; the newest is latest().
    std::size_t feed(std::string_view bytes);

    /// The newest good sample (channels == 0 before the first).
    const Sample& latest() const { return m_latest; }
    /// The newest identification, if any came.
    const std::optional<Identification>& identification() const { return m_identification; }
    /// Values a sample line must have: the identification's channels, or before any
    /// identification those of the first good sample line; 0 while unknown.
    int channels() const { return m_channels; }
    const Stats& stats() const { return m_stats; }
    /// Bytes of the unfinished line held (≤ kMaxLineLength + 1): the parser's memory.
    std::size_t bufferedBytes() const { return m_line.size(); }

    /// The stream restarts (port reopened): forgets the unfinished line and the seq
    /// continuity; keeps statistics, the identification and the channel count.
    void resetStream();
    /// Back to the state after construction.
    void reset();

private:
    enum class State { Idle, InLine, Skipping };

    void endLine();  // a '\n' completed the line in m_line
    void parseSample(std::string_view body);
    void parseIdentification(std::string_view body);

    State m_state = State::Idle;
    bool m_junk = false;      // bytes other than "\r" seen on this line before a marker
    std::string m_line;       // marker and what follows, up to kMaxLineLength + 1 bytes
    std::size_t m_newSamples = 0;
    Sample m_latest;
    std::optional<Identification> m_identification;
    int m_channels = 0;
    std::optional<std::uint16_t> m_lastSeq;
    Stats m_stats;
};

}  // namespace trainer::daq
