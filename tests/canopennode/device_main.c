/* A host CANopenNode device for the tests: CO_new, CO_CANinit, LSS, CO_CANopenInit and
 * CO_CANopenInitPDO with the generated OD, then ITERATIONS passes of the main loop (1 ms of
 * simulated time each). Exit code 0 and "operational" when every step succeeded. */
#include <stdio.h>
#include <stdlib.h>
#include "CANopen.h"
#include "OD.h"

#define NMT_CONTROL (CO_NMT_STARTUP_TO_OPERATIONAL | CO_NMT_ERR_ON_ERR_REG | CO_ERR_REG_GENERIC_ERR)

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
    CO_CANsetConfigurationMode(NULL);
    CO_CANmodule_disable(co->CANmodule);
    CO_ReturnError_t err = CO_CANinit(co, NULL, bitRate);
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
    CO_CANsetNormalMode(co->CANmodule);
    for (unsigned long i = 0; i < iterations; i++) {
        CO_NMT_reset_cmd_t reset = CO_process(co, false, 1000, NULL);
#if ((CO_CONFIG_SYNC)&CO_CONFIG_SYNC_ENABLE) != 0
        bool_t syncWas = CO_process_SYNC(co, 1000, NULL);
#else
        bool_t syncWas = false;
#endif
        CO_process_RPDO(co, syncWas, 1000, NULL);
        CO_process_TPDO(co, syncWas, 1000, NULL);
        if (reset != CO_RESET_NOT) {
            printf("reset %d after %lu iterations\n", reset, i);
            return 7;
        }
    }
    CO_NMT_internalState_t state = CO_NMT_getInternalState(co->NMT);
    printf("%s after %lu iterations\n", state == CO_NMT_OPERATIONAL ? "operational" : "not operational", iterations);
    CO_delete(co);
    return state == CO_NMT_OPERATIONAL ? 0 : 8;
}
