#pragma once
#include <cstdint>

// Register addresses and bits of the AT91SAM7S256 that nxtmap's firmware uses (absolute addresses,
// from the Atmel header as summarised in docs: see firmware/README.md). Only what the drivers touch.
namespace nxtmap::fw::reg {

// Peripheral identifiers (AIC source numbers, PMC_PCER bits).
enum PeripheralId : uint32_t {
  kIdSys = 1,
  kIdPioa = 2,
  kIdAdc = 4,
  kIdSpi = 5,
  kIdUsart1 = 7,
  kIdTwi = 9,
  kIdTc0 = 12,
};
// The bit of peripheral `id` in PMC_PCER and the AIC's enable/disable/clear registers.
constexpr uint32_t peripheralBit(uint32_t id) { return 1u << id; }

// AIC
constexpr uint32_t kAicSmr = 0xFFFFF000;  // + 4 * id
constexpr uint32_t kAicSvr = 0xFFFFF080;  // + 4 * id
constexpr uint32_t kAicIvr = 0xFFFFF100;
constexpr uint32_t kAicIecr = 0xFFFFF120;
constexpr uint32_t kAicIdcr = 0xFFFFF124;
constexpr uint32_t kAicIccr = 0xFFFFF128;
constexpr uint32_t kAicEoicr = 0xFFFFF130;
constexpr uint32_t kAicSpu = 0xFFFFF134;
constexpr uint32_t kAicDcr = 0xFFFFF138;
constexpr uint32_t kAicFfdr = 0xFFFFF144;

// PIO A
constexpr uint32_t kPioPer = 0xFFFFF400;
constexpr uint32_t kPioPdr = 0xFFFFF404;
constexpr uint32_t kPioOer = 0xFFFFF410;
constexpr uint32_t kPioOdr = 0xFFFFF414;
constexpr uint32_t kPioIfer = 0xFFFFF420;
constexpr uint32_t kPioSodr = 0xFFFFF430;
constexpr uint32_t kPioCodr = 0xFFFFF434;
constexpr uint32_t kPioPdsr = 0xFFFFF43C;
constexpr uint32_t kPioIer = 0xFFFFF440;
constexpr uint32_t kPioIdr = 0xFFFFF444;
constexpr uint32_t kPioIsr = 0xFFFFF44C;
constexpr uint32_t kPioMder = 0xFFFFF450;
constexpr uint32_t kPioMddr = 0xFFFFF454;
constexpr uint32_t kPioPpudr = 0xFFFFF460;
constexpr uint32_t kPioAsr = 0xFFFFF470;
constexpr uint32_t kPioBsr = 0xFFFFF474;

// PMC / CKGR
constexpr uint32_t kPmcScdr = 0xFFFFFC04;
constexpr uint32_t kPmcScdrPck = 1u << 0;  // processor clock off until the next interrupt
constexpr uint32_t kPmcPcer = 0xFFFFFC10;
constexpr uint32_t kCkgrMor = 0xFFFFFC20;
constexpr uint32_t kCkgrPllr = 0xFFFFFC2C;
constexpr uint32_t kPmcMckr = 0xFFFFFC30;
constexpr uint32_t kPmcSr = 0xFFFFFC68;
constexpr uint32_t kPmcSrMoscs = 1u << 0, kPmcSrLock = 1u << 2, kPmcSrMckrdy = 1u << 3;

// RSTC, PIT, WDT
constexpr uint32_t kRstcRmr = 0xFFFFFD08;
constexpr uint32_t kPitMr = 0xFFFFFD30;
constexpr uint32_t kPitSr = 0xFFFFFD34;
constexpr uint32_t kPitPivr = 0xFFFFFD38;
constexpr uint32_t kWdtCr = 0xFFFFFD40;
constexpr uint32_t kWdtMr = 0xFFFFFD44;
constexpr uint32_t kPitMrPiten = 1u << 24, kPitMrPitien = 1u << 25;  // timer on, its interrupt on
constexpr uint32_t kPitMrPivMask = 0xFFFFFu;                         // period - 1, in MCK/16 ticks
constexpr uint32_t kPitSrPits = 1u << 0;                             // a period ended since PIVR was read
constexpr uint32_t kPitPivrPicntShift = 20;                          // PICNT: periods since PIVR was read
constexpr uint32_t kWdtCrKey = 0xA5u << 24, kWdtCrWdrstt = 1u << 0;  // restart the watchdog

// MC / EFC
constexpr uint32_t kMcRcr = 0xFFFFFF00;
constexpr uint32_t kMcFmr = 0xFFFFFF60;
constexpr uint32_t kMcFcr = 0xFFFFFF64;  // FKEY 0x5A in 31..24, page in 17..8, command in 3..0
constexpr uint32_t kMcFsr = 0xFFFFFF68;  // FRDY 0, LOCKE 2, PROGE 3, lock bits 31..16 (one per 64 pages)
constexpr uint32_t kMcFcrKey = 0x5Au << 24, kMcFcrWp = 0x1u, kMcFcrClb = 0x4u;
constexpr uint32_t kMcFsrLocke = 1u << 2, kMcFsrProge = 1u << 3, kMcFsrLocksShift = 16;
constexpr uint32_t kFlashBase = 0x00100000, kFlashPageBytes = 256, kFlashPagesPerRegion = 64;

// TWI (AVR link)
constexpr uint32_t kTwiCr = 0xFFFB8000;
constexpr uint32_t kTwiMmr = 0xFFFB8004;
constexpr uint32_t kTwiCwgr = 0xFFFB8010;
constexpr uint32_t kTwiSr = 0xFFFB8020;
constexpr uint32_t kTwiIer = 0xFFFB8024;
constexpr uint32_t kTwiIdr = 0xFFFB8028;
constexpr uint32_t kTwiRhr = 0xFFFB8030;
constexpr uint32_t kTwiThr = 0xFFFB8034;
constexpr uint32_t kTwiCrStart = 1u << 0, kTwiCrStop = 1u << 1, kTwiCrMsen = 1u << 2, kTwiCrMsdis = 1u << 3,
                   kTwiCrSwrst = 1u << 7;
constexpr uint32_t kTwiSrTxcomp = 1u << 0, kTwiSrRxrdy = 1u << 1, kTwiSrTxrdy = 1u << 2, kTwiSrOvre = 1u << 6,
                   kTwiSrUnre = 1u << 7, kTwiSrNack = 1u << 8;
constexpr uint32_t kTwiMmrMread = 1u << 12;

// USART1 (Bluetooth) and its PDC
constexpr uint32_t kUs1Cr = 0xFFFC4000;
constexpr uint32_t kUs1Mr = 0xFFFC4004;
constexpr uint32_t kUs1Ier = 0xFFFC4008;
constexpr uint32_t kUs1Idr = 0xFFFC400C;
constexpr uint32_t kUs1Csr = 0xFFFC4014;
constexpr uint32_t kUs1Rhr = 0xFFFC4018;
constexpr uint32_t kUs1Brgr = 0xFFFC4020;
constexpr uint32_t kUs1Rpr = 0xFFFC4100;
constexpr uint32_t kUs1Rcr = 0xFFFC4104;
constexpr uint32_t kUs1Tpr = 0xFFFC4108;
constexpr uint32_t kUs1Tcr = 0xFFFC410C;
constexpr uint32_t kUs1Tnpr = 0xFFFC4118;  // PDC transmit next pointer: taken when TCR reaches 0
constexpr uint32_t kUs1Tncr = 0xFFFC411C;  // PDC transmit next counter
constexpr uint32_t kUs1Rnpr = 0xFFFC4110;
constexpr uint32_t kUs1Rncr = 0xFFFC4114;
constexpr uint32_t kUs1Ptcr = 0xFFFC4120;
constexpr uint32_t kUsCsrRxrdy = 1u << 0, kUsCsrOvre = 1u << 5, kUsCsrEndtx = 1u << 4, kUsCsrTxempty = 1u << 9;

// SPI (LCD) and its PDC
constexpr uint32_t kSpiCr = 0xFFFE0000;
constexpr uint32_t kSpiMr = 0xFFFE0004;
constexpr uint32_t kSpiTdr = 0xFFFE000C;
constexpr uint32_t kSpiSr = 0xFFFE0010;
constexpr uint32_t kSpiCsr2 = 0xFFFE0038;
constexpr uint32_t kSpiTpr = 0xFFFE0108;
constexpr uint32_t kSpiTcr = 0xFFFE010C;
constexpr uint32_t kSpiPtcr = 0xFFFE0120;
constexpr uint32_t kSpiSrTdre = 1u << 1, kSpiSrTxempty = 1u << 9;

// ADC (channel 6 = BlueCore CMD line)
constexpr uint32_t kAdcCr = 0xFFFD8000;
constexpr uint32_t kAdcMr = 0xFFFD8004;
constexpr uint32_t kAdcCher = 0xFFFD8010;
constexpr uint32_t kAdcSr = 0xFFFD801C;
constexpr uint32_t kAdcCdr6 = 0xFFFD8048;

// TC0 (soft I2C bit clock)
constexpr uint32_t kTc0Ccr = 0xFFFA0000;
constexpr uint32_t kTc0Cmr = 0xFFFA0004;
constexpr uint32_t kTc0Rc = 0xFFFA001C;
constexpr uint32_t kTc0Sr = 0xFFFA0020;
constexpr uint32_t kTc0Ier = 0xFFFA0024;
constexpr uint32_t kTcCcrClken = 1u << 0, kTcCcrClkdis = 1u << 1, kTcCcrSwtrg = 1u << 2;
constexpr uint32_t kTcCmrTimerClock1 = 0u;   // TCCLKS: MCK/2
constexpr uint32_t kTcCmrCpctrg = 1u << 14;  // counter reset on RC compare
constexpr uint32_t kTcSrCpcs = 1u << 4;      // RC compare (TC_SR, TC_IER)

// PIO A pins of the NXT board.
constexpr uint32_t pin(int n) { return 1u << n; }
constexpr uint32_t kPinTachoC = pin(0), kPinDirA = pin(1), kPinTwd = pin(3), kPinTwck = pin(4), kPinDirC = pin(8),
                   kPinDirB = pin(9), kPinLcdCs = pin(10), kPinBtReset = pin(11), kPinLcdA0 = pin(12),
                   kPinLcdMosi = pin(13), kPinLcdSpck = pin(14), kPinTachoA = pin(15), kPinBtRxd = pin(21),
                   kPinBtTxd = pin(22), kPinBtRts = pin(24), kPinBtCts = pin(25), kPinTachoB = pin(26),
                   kPinBtArm7Cmd = pin(27), kPinBtCs = pin(31);

// Master clock: 18.432 MHz crystal x 73 / 14 / 2.
constexpr uint32_t kMck = 48054857;

}  // namespace nxtmap::fw::reg
