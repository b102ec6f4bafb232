// grbl 1.1's status codes (its report.h / the error list of its documentation) that this firmware answers.
#pragma once

#define STATUS_OK 0
#define STATUS_EXPECTED_COMMAND_LETTER 1
#define STATUS_BAD_NUMBER_FORMAT 2
#define STATUS_INVALID_STATEMENT 3
#define STATUS_NEGATIVE_VALUE 4
#define STATUS_OVERFLOW 11
#define STATUS_UNSUPPORTED_COMMAND 20
#define STATUS_UNDEFINED_FEED_RATE 22
