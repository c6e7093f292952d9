/* A host CANopenNode device for the tests: CO_new, CO_CANinit, LSS, CO_CANopenInit and
 * CO_CANopenInitPDO with the generated OD, then ITERATIONS passes of the main loop.
 *
 * With the blank driver each pass simulates 1 ms and the device starts itself; exit code 0 and
 * "operational" when every step succeeded. Built with -DDEVICE_TCP and hostcan/CO_driver_tcp.c,
 * `device ITERATIONS PORT` connects to the test on 127.0.0.1:PORT, runs in real time (about 1 ms
 * per pass), waits for NMT start like any node, and ends when the test closes the link.
 *
 * With -DDEVICE_APPLICATION the application of CANopenDemo (its CO_application.c) is linked in and its
 * hooks are called where CANopenLinux's main calls them; with -DDEVICE_IDENTIFICATORS only the demo's
 * CO_identificators_init runs at start; without either the hooks do nothing. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include "CANopen.h"
#include "OD.h"

#ifdef DEVICE_APPLICATION
#include "CO_application.h"
#else
#ifdef DEVICE_IDENTIFICATORS
#include "CO_identificators.h"
#endif
static CO_ReturnError_t
app_programStart(uint16_t* bitRate, uint8_t* nodeId, uint32_t* errInfo) {
#ifdef DEVICE_IDENTIFICATORS
    CO_identificators_init(bitRate, nodeId);
#else
    (void)bitRate;
    (void)nodeId;
#endif
    (void)errInfo;
    return CO_ERROR_NO;
}
static void
app_communicationReset(CO_t* co) {
    (void)co;
}
static void
app_programEnd(void) {}
static void
app_programAsync(CO_t* co, uint32_t timer1usDiff) {
    (void)co;
    (void)timer1usDiff;
}
static void
app_programRt(CO_t* co, uint32_t timer1usDiff) {
    (void)co;
    (void)timer1usDiff;
}
#endif

#ifdef DEVICE_TCP
#include <time.h>
int CO_CANconnect(unsigned port);
#define NMT_CONTROL 0
#else
#define NMT_CONTROL (CO_NMT_STARTUP_TO_OPERATIONAL | CO_NMT_ERR_ON_ERR_REG | CO_ERR_REG_GENERIC_ERR)
#endif

int
main(int argc, char** argv) {
    unsigned long iterations = argc > 1 ? strtoul(argv[1], NULL, 10) : 1000UL;
    uint8_t nodeId = 10;
    uint16_t bitRate = 125;
    uint32_t heapUsed = 0;
    uint32_t errInfo = 0;
    CO_config_t* config = NULL;
#ifdef CO_MULTIPLE_OD
    CO_config_t multipleConfig = {0};
    OD_INIT_CONFIG(multipleConfig);
    multipleConfig.CNT_LEDS = 1;
    multipleConfig.CNT_LSS_SLV = 1;
    config = &multipleConfig;
#endif
    CO_t* co = CO_new(config, &heapUsed);
    if (co == NULL) {
        printf("CO_new failed\n");
        return 2;
    }
    CO_ReturnError_t err = app_programStart(&bitRate, &nodeId, &errInfo);
    if (err != CO_ERROR_NO) {
        printf("app_programStart: %d, OD entry 0x%lX\n", err, (unsigned long)errInfo);
        return 10;
    }
    void* canPtr = NULL;
#ifdef DEVICE_TCP
    int link = CO_CANconnect(argc > 2 ? (unsigned)strtoul(argv[2], NULL, 10) : 0U);
    if (link < 0) {
        printf("cannot connect to the test\n");
        return 9;
    }
    canPtr = (void*)(intptr_t)link;
#endif
    CO_CANsetConfigurationMode(canPtr);
    CO_CANmodule_disable(co->CANmodule);
    err = CO_CANinit(co, canPtr, bitRate);
    if (err != CO_ERROR_NO) {
        printf("CO_CANinit: %d\n", err);
        return 3;
    }
    CO_LSS_address_t lss = {{0}};
    err = CO_LSSinit(co, &lss, &nodeId, &bitRate);
    if (err != CO_ERROR_NO) {
        printf("CO_LSSinit: %d\n", err);
        return 4;
    }
    err = CO_CANopenInit(co, NULL, NULL, OD, NULL, NMT_CONTROL, 500, 1000, 500, false, nodeId, &errInfo);
    if (err != CO_ERROR_NO) {
        printf("CO_CANopenInit: %d, OD entry 0x%lX\n", err, (unsigned long)errInfo);
        return 5;
    }
    err = CO_CANopenInitPDO(co, co->em, OD, nodeId, &errInfo);
    if (err != CO_ERROR_NO) {
        printf("CO_CANopenInitPDO: %d, OD entry 0x%lX\n", err, (unsigned long)errInfo);
        return 6;
    }
    app_communicationReset(co);
    CO_CANsetNormalMode(co->CANmodule);
    for (unsigned long i = 0; i < iterations; i++) {
#ifdef DEVICE_TCP
        struct timespec pause = {0, 1000000L};
        nanosleep(&pause, NULL);
        if (!CO_CANpoll(co->CANmodule)) {
            printf("link closed after %lu iterations\n", i);
            app_programEnd();
            CO_delete(co);
            return 0;
        }
#endif
        CO_NMT_reset_cmd_t reset = CO_process(co, false, 1000, NULL);
        app_programAsync(co, 1000);
#if ((CO_CONFIG_SYNC)&CO_CONFIG_SYNC_ENABLE) != 0
        bool_t syncWas = CO_process_SYNC(co, 1000, NULL);
#else
        bool_t syncWas = false;
#endif
        CO_process_RPDO(co, syncWas, 1000, NULL);
        CO_process_TPDO(co, syncWas, 1000, NULL);
        app_programRt(co, 1000);
        if (reset != CO_RESET_NOT) {
            printf("reset %d after %lu iterations\n", reset, i);
            return 7;
        }
    }
    CO_NMT_internalState_t state = CO_NMT_getInternalState(co->NMT);
    printf("%s after %lu iterations\n", state == CO_NMT_OPERATIONAL ? "operational" : "not operational", iterations);
    app_programEnd();
    CO_delete(co);
    return state == CO_NMT_OPERATIONAL ? 0 : 8;
}
