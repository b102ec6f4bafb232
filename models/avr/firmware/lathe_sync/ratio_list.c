#include "ratio_list.h"

uint32_t ratio_x(uint16_t pitch_centi_mm) { return (uint32_t)RATIO_LS_PPR * pitch_centi_mm * 10u; }

uint32_t ratio_y(void) { return (uint32_t)RATIO_SP_PPR * RATIO_LS_PITCH; }

static int32_t magnitude(int32_t v) { return v < 0 ? -v : v; }

ratio_fraction ratio_best(uint16_t pitch_centi_mm) {
    const int32_t x = (int32_t)ratio_x(pitch_centi_mm);
    const int32_t y = (int32_t)ratio_y();
    int32_t error = x;
    uint16_t countx = 0;
    ratio_fraction best = {0, 0, 0};
    for (uint16_t n = 1; n <= RATIO_MAX_DEN; ++n) {
        while (error > y / 2) {  /* countx = round(n x / y), error = n x - countx y in (-y/2, y/2] */
            error -= y;
            ++countx;
        }
        if (best.den == 0 || magnitude(error) < magnitude(best.residual)) {
            best.num = countx;
            best.den = n;
            best.residual = error;
        }
        if (error == 0) break;
        error += x;
    }
    return best;
}

ratio_fraction ratio_best_as_printed(uint16_t pitch_centi_mm) {
    const uint32_t x = ratio_x(pitch_centi_mm);
    const uint32_t y = ratio_y();
    int32_t bError = (int32_t)x;
    uint16_t countx = 0;
    uint16_t iterations = 0;
    int32_t bestError = bError;
    ratio_fraction best = {0, 0, 0};
    while (bError != 0 && iterations < RATIO_MAX_DEN) {
        iterations++;
        /* The listing's int32/uint32 comparison and arithmetic, spelt out: C converts bError to uint32. */
        while ((uint32_t)bError > y / 2) {
            bError = (int32_t)((uint32_t)bError - y);
            countx++;
        }
        if (bError < bestError) {
            bestError = bError;
            best.num = countx;
            best.den = iterations;
        }
        bError = (int32_t)((uint32_t)bError + x);
    }
    best.residual = bestError;
    return best;
}

uint8_t ratio_next(uint16_t* rem, uint16_t num, uint16_t den) {
    uint32_t error = (uint32_t)*rem + num;
    uint8_t count = 0;
    while (error >= den) {
        error -= den;
        count++;
    }
    *rem = (uint16_t)error;
    return count;
}
