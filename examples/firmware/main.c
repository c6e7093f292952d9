/* Uses the code cantools-od generates from eds/cia402_drive.eds (NAME drive, node-ID 5): fills a TPDO,
 * packs it into a CAN frame, unpacks the frame and checks that the values come back unchanged. */
#include <stdio.h>
#include <string.h>

#include "drive.h"

static const struct drive_object_info *find_object(uint16_t index, uint8_t subindex)
{
    size_t i;

    for (i = 0u; i < DRIVE_OBJECT_COUNT; ++i) {
        if (drive_objects[i].index == index && drive_objects[i].subindex == subindex) {
            return &drive_objects[i];
        }
    }
    return NULL;
}

int main(void)
{
    struct drive_od od;
    struct drive_tpdo2 sent;
    struct drive_tpdo2 received;
    uint8_t frame[DRIVE_PDO_MAX_DLC];
    const struct drive_object_info *statusword = find_object(DRIVE_STATUSWORD_INDEX, DRIVE_STATUSWORD_SUBINDEX);
    int length;
    int i;

    drive_init(&od, DRIVE_NODE_ID);
    printf("heartbeat %u ms\n", (unsigned)od.producer_heartbeat_time);

    /* The object table says where a value lives in struct drive_od, as an SDO server needs. */
    if (statusword == NULL || statusword->size != sizeof od.statusword) {
        fprintf(stderr, "statusword is not in the object table\n");
        return 1;
    }
    od.statusword = 0x0637u;

    memset(&sent, 0, sizeof sent);
    memcpy(&sent.statusword, (const uint8_t *)&od + statusword->offset, statusword->size);
    sent.position_actual_value = -123456;
    sent.torque_actual_value = -42;

    length = drive_tpdo2_pack(frame, &sent, sizeof frame);
    if (length != (int)DRIVE_TPDO2_DLC) {
        fprintf(stderr, "pack failed: %d\n", length);
        return 1;
    }
    printf("TPDO2 0x%03lX [%d]", (unsigned long)DRIVE_TPDO2_COB_ID(DRIVE_NODE_ID), length);
    for (i = 0; i < length; ++i) {
        printf(" %02X", frame[i]);
    }
    printf("\n");

    if (drive_tpdo2_unpack(&received, frame, (size_t)length) != length) {
        fprintf(stderr, "unpack failed\n");
        return 1;
    }
    if (received.statusword != sent.statusword || received.position_actual_value != sent.position_actual_value ||
        received.torque_actual_value != sent.torque_actual_value) {
        fprintf(stderr, "round trip mismatch\n");
        return 1;
    }
    if (drive_rpdo2_target_position_is_in_range(2000000000) || !drive_rpdo2_target_position_is_in_range(-5)) {
        fprintf(stderr, "target position limits not applied\n");
        return 1;
    }
    printf("round trip ok\n");
    return 0;
}
