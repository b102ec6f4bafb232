// A firmware for another MCU (built with -mmcu=atmega88 and a .mmcu section naming it): the model must refuse it.
#include "fw_test.h"

int main(void) {
    fw_end();
}
