/* The application interface CANopenDemo's CO_application.c implements: the five hooks a CANopenNode main
 * calls (CANopenLinux declares them; its header is not part of the demo folder, so the test device
 * declares them here). device_main.c calls each where a CANopenNode main does. */
#ifndef CO_APPLICATION_H
#define CO_APPLICATION_H

#include "CANopen.h"

/* Once, before the first communication reset: bit rate and node-ID, and the OD extensions. */
CO_ReturnError_t app_programStart(uint16_t* bitRate, uint8_t* nodeId, uint32_t* errInfo);
/* After every communication reset (CO_CANopenInit and CO_CANopenInitPDO). */
void app_communicationReset(CO_t* co);
/* Once, when the program ends. */
void app_programEnd(void);
/* Every pass of the main loop. */
void app_programAsync(CO_t* co, uint32_t timer1usDiff);
/* Every pass of the real-time loop (here the same loop). */
void app_programRt(CO_t* co, uint32_t timer1usDiff);

#endif /* CO_APPLICATION_H */
