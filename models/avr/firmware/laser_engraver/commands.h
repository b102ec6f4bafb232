/* The command routines of seed 003 §5.4 (App. A2-A4), each entered after its ID byte. */
#pragma once

void cmd_g00(void);  /* App. A2: both axes at v_max, X counted in the Timer0 ISR, Y by polling */
void cmd_g01(void);  /* App. A3: X counted by polling, Y follows from the speed ratio */
void cmd_arc(void);  /* App. A4: G02 and G03, chords double-buffered, X counted in the ISR */
void cmd_m30(void);  /* §5.4.5: head off, sleep */
