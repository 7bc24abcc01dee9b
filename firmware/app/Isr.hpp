#pragma once
// The interrupt handlers (ARM code, defined in main.cpp), installed into the AIC by BrickApp::init.
extern "C" {
void nxtmapIsrSystem();
void nxtmapIsrPio();
void nxtmapIsrTwi();
void nxtmapIsrUsart1();
void nxtmapIsrTc0();
void nxtmapIsrSsc();
void nxtmapIsrSpurious();
}
