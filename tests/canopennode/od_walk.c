/* Walks a CANopenNode object dictionary through the stack's own OD_find/OD_getSub and prints
 * what the stack sees: per object its index, sub-entry count and type; per sub-entry its
 * attribute, data length, the storage group its memory is in, and the bytes there.
 * Built by the tests with -DOD_GROUPS='G(RAM) G(PERSIST_COMM) ...' (the groups OD.h declares). */
#define OD_DEFINITION
#include <stdio.h>
#include "301/CO_ODinterface.h"
#include "OD.h"

#ifndef OD_GROUPS
#define OD_GROUPS
#endif

struct group {
    const char* name;
    const uint8_t* start;
    size_t size;
};

#define G(name) {#name, (const uint8_t*)&OD_##name, sizeof(OD_##name)},
static const struct group groups[] = {OD_GROUPS{NULL, NULL, 0}};

static const char*
group_of(const void* data) {
    const uint8_t* at = (const uint8_t*)data;
    for (size_t i = 0; groups[i].name != NULL; i++) {
        if (at >= groups[i].start && at < groups[i].start + groups[i].size) {
            return groups[i].name;
        }
    }
    return "?";
}

int
main(void) {
    for (uint16_t n = 0; n < OD->size; n++) {
        OD_entry_t* listed = &OD->list[n];
        OD_entry_t* found = OD_find(OD, listed->index);
        if (found != listed) {
            printf("NOTFOUND %04X\n", listed->index);
            return 1;
        }
        printf("O %04X %u %u\n", found->index, found->subEntriesCount, found->odObjectType & ODT_TYPE_MASK);
        for (unsigned sub = 0; sub < 256; sub++) {
            OD_IO_t io;
            if (OD_getSub(found, (uint8_t)sub, &io, true) != ODR_OK) {
                continue;
            }
            const uint8_t* data = (const uint8_t*)io.stream.dataOrig;
            printf("S %u %u %lu %s ", sub, io.stream.attribute, (unsigned long)io.stream.dataLength,
                   data != NULL ? group_of(data) : "-");
            if (data == NULL) {
                printf("-");
            }
            for (OD_size_t i = 0; data != NULL && i < io.stream.dataLength; i++) {
                printf("%02x", data[i]);
            }
            printf("\n");
        }
    }
    return 0;
}
