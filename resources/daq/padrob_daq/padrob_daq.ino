// padrob_daq: reference firmware of the Padrob DAQ console (docs/daq-protocol.md).
//
// Board: Arduino Nano (ATmega328P, 16 MHz, 5 V). Eight levers, each turning a linear
// potentiometer (10 kΩ) wired 5V – wiper – GND, wipers on A0…A7; the 10-bit ADC
// reads them 0…1023. Sends the identification at power-up and on "?", then one
// sample line per period:
//   #PADROB-DAQ,1,8,10,<rate>,Padrob Nano console*CC
//   $<seq>,<A0>,…,<A7>*CC
// Commands (lines from the host): "?" identification, "R<hz>" sample rate 1…1000
// (answered with the identification, showing the rate in force; kept until reset).
//
// Throughput: a line of eight 4-digit readings is about 47 bytes; at 115200 baud that
// is 4 ms, and the eight conversions take 0.9 ms, so the box really sends about 200
// lines/s at most. A higher rate runs flat out (no seq gaps: seq counts lines sent).
// Build with the Arduino IDE or arduino-cli (board "Arduino Nano"); set BAUD to the
// rate chosen in the host's device settings.

#include <Arduino.h>
#include <stdlib.h>
#include <string.h>

// ---- settings -------------------------------------------------------------------
static const unsigned long BAUD = 115200;     // must match the host
static const uint8_t CHANNELS = 8;            // A0…A7
static const uint8_t PINS[CHANNELS] = {A0, A1, A2, A3, A4, A5, A6, A7};
static const uint8_t BITS = 10;               // the ATmega328P's ADC
static const uint16_t DEFAULT_RATE = 100;     // [Hz] at power-up
static const char NAME[] = "Padrob Nano console";  // printable ASCII, no , * $ #

// ---- state ------------------------------------------------------------------------
static uint16_t rateHz = DEFAULT_RATE;
static uint32_t periodUs = 1000000UL / DEFAULT_RATE;
static uint32_t nextDue;   // [µs] micros() of the next sample
static uint16_t seq = 0;   // wraps 65535 → 0
static char cmd[8];        // the host's line being received
static uint8_t cmdLen = 0;
static bool cmdTooLong = false;

// CRC-8/SMBUS: polynomial 0x07, init 0x00, not reflected, no final xor.
// crc8("123456789", 9) == 0xF4.
uint8_t crc8(const char *p, uint8_t n)
{
    uint8_t crc = 0x00;
    while (n--) {
        crc ^= (uint8_t)*p++;
        for (uint8_t i = 0; i < 8; i++)
            crc = (crc & 0x80) ? (uint8_t)((crc << 1) ^ 0x07) : (uint8_t)(crc << 1);
    }
    return crc;
}

// marker, body, "*", two uppercase hex digits of the body's CRC, "\n"
static void sendLine(char marker, const char *body, uint8_t n)
{
    static const char hex[] = "0123456789ABCDEF";
    const uint8_t crc = crc8(body, n);
    const char tail[4] = {'*', hex[crc >> 4], hex[crc & 0x0F], '\n'};
    Serial.write(marker);
    Serial.write((const uint8_t *)body, n);
    Serial.write((const uint8_t *)tail, 4);
}

static void sendIdentification()
{
    char body[64];
    const int n = snprintf(body, sizeof body, "PADROB-DAQ,1,%u,%u,%u,%s", (unsigned)CHANNELS,
                           (unsigned)BITS, (unsigned)rateHz, NAME);
    sendLine('#', body, (uint8_t)n);
}

static void sendSample()
{
    char body[6 + 6 * CHANNELS];  // "65535" and ",1023" × 8, with room to spare
    char *p = body;
    utoa(seq, p, 10);
    p += strlen(p);
    for (uint8_t i = 0; i < CHANNELS; i++) {
        *p++ = ',';
        utoa((unsigned)analogRead(PINS[i]), p, 10);
        p += strlen(p);
    }
    sendLine('$', body, (uint8_t)(p - body));
    seq++;
}

// "?" or "R<hz>"; anything else is ignored
static void runCommand()
{
    if (cmdLen == 1 && cmd[0] == '?') {
        sendIdentification();
    } else if (cmdLen >= 2 && cmdLen <= 5 && cmd[0] == 'R') {
        uint16_t hz = 0;
        for (uint8_t i = 1; i < cmdLen; i++) {
            if (cmd[i] < '0' || cmd[i] > '9')
                return;
            hz = hz * 10 + (uint16_t)(cmd[i] - '0');  // ≤ 9999: no overflow
        }
        if (hz >= 1 && hz <= 1000) {
            rateHz = hz;
            periodUs = 1000000UL / hz;
            nextDue = micros();
        }
        sendIdentification();  // the rate in force, changed or not
    }
}

static void readCommands()
{
    while (Serial.available() > 0) {
        const char c = (char)Serial.read();
        if (c == '\r')
            continue;
        if (c == '\n') {
            if (!cmdTooLong)
                runCommand();
            cmdLen = 0;
            cmdTooLong = false;
        } else if (cmdLen < sizeof cmd) {
            cmd[cmdLen++] = c;
        } else {
            cmdTooLong = true;
        }
    }
}

void setup()
{
    Serial.begin(BAUD);
    sendIdentification();
    nextDue = micros();
}

void loop()
{
    readCommands();
    const uint32_t now = micros();
    if ((int32_t)(now - nextDue) >= 0) {
        nextDue += periodUs;
        if ((int32_t)(now - nextDue) >= 0)
            nextDue = now + periodUs;  // fell behind: no burst to catch up
        sendSample();
    }
}
