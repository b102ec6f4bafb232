// The block queue and the step generator: each block is a straight move at one rate, stepped by Bresenham in
// Timer1's compare ISR (CTC, one interrupt per step of the dominant axis), as grbl's stepper.c does without its
// acceleration (AMASS and the segment buffer). The laser's power is a block's too: the ISR sets OC2A's duty when the
// block starts, as grbl's laser mode does at each segment.
#pragma once
#include <stdint.h>

#define BLOCK_BUFFER_SIZE 16  // grbl's for the 328P

void motion_init(void);
// Queues a move of (dx, dy) steps with the dominant axis stepping every `cycles` CPU cycles, the laser at OCR2A
// (OCR2 on the ATmega16) `laser_ocr` (0: off) while it runs; waits while the queue is full (answering status
// requests). A move of no step only sets the laser.
void motion_queue(int32_t dx, int32_t dy, uint32_t cycles, uint8_t laser_ocr);
// No block queued or running.
uint8_t motion_idle(void);
// The steps made so far (the machine position).
void motion_position(int32_t out[2]);
// The laser's power between moves (M5, or M3 outside laser mode; laser mode: off): OCR2A
// (OCR2), 0 switches OC2A (OC2) off.
void motion_laser(uint8_t laser_ocr);
