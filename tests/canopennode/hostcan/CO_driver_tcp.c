/* CANopenNode CAN driver for host tests: frames travel over one TCP connection to 127.0.0.1, 16 bytes
 * each: identifier (4 bytes, little-endian, bit 30 = RTR), DLC (1), 3 zero bytes, 8 data bytes. */
#include <arpa/inet.h>
#include <errno.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <string.h>
#include <sys/socket.h>
#include <unistd.h>

#include "301/CO_driver.h"

#define FRAME_SIZE 16U
#define RTR_BIT    0x40000000UL

static uint8_t pending[FRAME_SIZE];
static size_t pendingLength = 0;

static int
socketOf(CO_CANmodule_t* CANmodule) {
    return (int)(intptr_t)CANmodule->CANptr;
}

void
CO_CANsetConfigurationMode(void* CANptr) {
    (void)CANptr;
}

void
CO_CANsetNormalMode(CO_CANmodule_t* CANmodule) {
    CANmodule->CANnormal = true;
}

CO_ReturnError_t
CO_CANmodule_init(CO_CANmodule_t* CANmodule, void* CANptr, CO_CANrx_t rxArray[], uint16_t rxSize, CO_CANtx_t txArray[],
                  uint16_t txSize, uint16_t CANbitRate) {
    (void)CANbitRate;
    if ((CANmodule == NULL) || (rxArray == NULL) || (txArray == NULL)) {
        return CO_ERROR_ILLEGAL_ARGUMENT;
    }
    CANmodule->CANptr = CANptr;
    CANmodule->rxArray = rxArray;
    CANmodule->rxSize = rxSize;
    CANmodule->txArray = txArray;
    CANmodule->txSize = txSize;
    CANmodule->CANerrorStatus = 0;
    CANmodule->CANnormal = false;
    CANmodule->useCANrxFilters = false;
    CANmodule->bufferInhibitFlag = false;
    CANmodule->firstCANtxMessage = true;
    CANmodule->CANtxCount = 0;
    CANmodule->errOld = 0;
    for (uint16_t i = 0; i < rxSize; i++) {
        rxArray[i].ident = 0;
        rxArray[i].mask = 0xFFFF;
        rxArray[i].object = NULL;
        rxArray[i].CANrx_callback = NULL;
    }
    for (uint16_t i = 0; i < txSize; i++) {
        txArray[i].bufferFull = false;
    }
    return CO_ERROR_NO;
}

void
CO_CANmodule_disable(CO_CANmodule_t* CANmodule) {
    (void)CANmodule;
}

CO_ReturnError_t
CO_CANrxBufferInit(CO_CANmodule_t* CANmodule, uint16_t index, uint16_t ident, uint16_t mask, bool_t rtr, void* object,
                   void (*CANrx_callback)(void* object, void* message)) {
    if ((CANmodule == NULL) || (object == NULL) || (CANrx_callback == NULL) || (index >= CANmodule->rxSize)) {
        return CO_ERROR_ILLEGAL_ARGUMENT;
    }
    CO_CANrx_t* buffer = &CANmodule->rxArray[index];
    buffer->object = object;
    buffer->CANrx_callback = CANrx_callback;
    buffer->ident = (uint16_t)((ident & 0x07FFU) | (rtr ? 0x0800U : 0U));
    buffer->mask = (uint16_t)((mask & 0x07FFU) | 0x0800U);
    return CO_ERROR_NO;
}

CO_CANtx_t*
CO_CANtxBufferInit(CO_CANmodule_t* CANmodule, uint16_t index, uint16_t ident, bool_t rtr, uint8_t noOfBytes,
                   bool_t syncFlag) {
    if ((CANmodule == NULL) || (index >= CANmodule->txSize)) {
        return NULL;
    }
    CO_CANtx_t* buffer = &CANmodule->txArray[index];
    buffer->ident = (uint32_t)(ident & 0x07FFU) | (rtr ? RTR_BIT : 0U);
    buffer->DLC = noOfBytes;
    buffer->bufferFull = false;
    buffer->syncFlag = syncFlag;
    return buffer;
}

static bool_t
writeAll(int fd, const uint8_t* data, size_t length) {
    while (length > 0U) {
        ssize_t written = send(fd, data, length, MSG_NOSIGNAL);
        if (written < 0 && errno == EINTR) {
            continue;
        }
        if (written <= 0) {
            return false;
        }
        data += written;
        length -= (size_t)written;
    }
    return true;
}

CO_ReturnError_t
CO_CANsend(CO_CANmodule_t* CANmodule, CO_CANtx_t* buffer) {
    uint8_t frame[FRAME_SIZE] = {0};
    uint32_t ident = buffer->ident;
    for (unsigned i = 0; i < 4U; i++) {
        frame[i] = (uint8_t)(ident >> (8U * i));
    }
    frame[4] = buffer->DLC;
    memcpy(&frame[8], buffer->data, 8);
    if (!writeAll(socketOf(CANmodule), frame, sizeof(frame))) {
        return CO_ERROR_TX_UNCONFIGURED;
    }
    CANmodule->firstCANtxMessage = false;
    return CO_ERROR_NO;
}

void
CO_CANclearPendingSyncPDOs(CO_CANmodule_t* CANmodule) {
    (void)CANmodule;
}

void
CO_CANmodule_process(CO_CANmodule_t* CANmodule) {
    (void)CANmodule;
}

static void
dispatch(CO_CANmodule_t* CANmodule, const uint8_t* frame) {
    uint32_t ident = (uint32_t)frame[0] | ((uint32_t)frame[1] << 8) | ((uint32_t)frame[2] << 16)
                     | ((uint32_t)frame[3] << 24);
    CO_CANrxMsg_t message;
    message.ident = (uint16_t)(ident & 0x07FFU);
    message.DLC = frame[4] > 8U ? 8U : frame[4];
    memcpy(message.data, &frame[8], 8);
    uint16_t key = (uint16_t)(message.ident | ((ident & RTR_BIT) != 0U ? 0x0800U : 0U));
    for (uint16_t i = 0; i < CANmodule->rxSize; i++) {
        CO_CANrx_t* buffer = &CANmodule->rxArray[i];
        if ((buffer->CANrx_callback != NULL) && (((key ^ buffer->ident) & buffer->mask) == 0U)) {
            buffer->CANrx_callback(buffer->object, &message);
            break;
        }
    }
}

bool_t
CO_CANpoll(CO_CANmodule_t* CANmodule) {
    int fd = socketOf(CANmodule);
    for (;;) {
        ssize_t got = recv(fd, &pending[pendingLength], FRAME_SIZE - pendingLength, MSG_DONTWAIT);
        if (got == 0) {
            return false;
        }
        if (got < 0) {
            return (errno == EAGAIN) || (errno == EWOULDBLOCK) || (errno == EINTR);
        }
        pendingLength += (size_t)got;
        if (pendingLength == FRAME_SIZE) {
            pendingLength = 0;
            if (CANmodule->CANnormal) {
                dispatch(CANmodule, pending);
            }
        }
    }
}

/* Connects to the test's listening port on 127.0.0.1; returns the socket or -1. */
int
CO_CANconnect(unsigned port) {
    int fd = socket(AF_INET, SOCK_STREAM, 0);
    if (fd < 0) {
        return -1;
    }
    struct sockaddr_in address;
    memset(&address, 0, sizeof(address));
    address.sin_family = AF_INET;
    address.sin_port = htons((uint16_t)port);
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (connect(fd, (struct sockaddr*)&address, sizeof(address)) != 0) {
        close(fd);
        return -1;
    }
    int one = 1;
    (void)setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof(one));
    return fd;
}
