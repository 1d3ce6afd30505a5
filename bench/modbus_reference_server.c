/* The reference for the DNC load benchmark (issue 13 item 6): the smallest Modbus TCP server
 * libmodbus makes, with the same map sizes as trilho's (core/dnc/register_map.h: 44 input
 * registers, 4114 holding registers), one thread, a select() loop over modbus_receive and
 * modbus_reply for any number of clients. What trilho-cli serve's Qt SerialBus server is
 * compared with; it validates nothing and drives no machine.
 * Usage: trilho-modbus-reference PORT [HOST=127.0.0.1]. Runs until SIGINT/SIGTERM (exit 0). */
#include <errno.h>
#include <modbus.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/select.h>
#include <unistd.h>

enum { kInputRegisters = 44, kHoldingRegisters = 4114 };

static volatile sig_atomic_t g_quit = 0;
static void onQuit(int sig) {
    (void)sig;
    g_quit = 1;
}

int main(int argc, char** argv) {
    if (argc < 2 || argc > 3) {
        fprintf(stderr, "usage: trilho-modbus-reference PORT [HOST=127.0.0.1]\n");
        return 64;
    }
    const int port = atoi(argv[1]);
    const char* host = argc > 2 ? argv[2] : "127.0.0.1";
    if (port < 1 || port > 65535) {
        fprintf(stderr, "trilho-modbus-reference: bad port '%s'\n", argv[1]);
        return 64;
    }
    modbus_t* ctx = modbus_new_tcp(host, port);
    modbus_mapping_t* map = modbus_mapping_new(0, 0, kHoldingRegisters, kInputRegisters);
    if (!ctx || !map) {
        fprintf(stderr, "trilho-modbus-reference: %s\n", modbus_strerror(errno));
        return 1;
    }
    map->tab_input_registers[0] = 1; /* protocol version, as trilho's input 0 */
    const int server = modbus_tcp_listen(ctx, 64);
    if (server < 0) {
        fprintf(stderr, "trilho-modbus-reference: cannot listen on %s:%d: %s\n", host, port,
                modbus_strerror(errno));
        return 1;
    }
    /* sigaction without SA_RESTART, so select() returns EINTR and the loop sees the flag. */
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = onQuit;
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    signal(SIGPIPE, SIG_IGN); /* a client gone mid-reply is a closed socket, not a death */
    printf("trilho-modbus-reference: Modbus TCP on %s:%d (input %d, holding %d registers)\n", host,
           port, kInputRegisters, kHoldingRegisters);
    fflush(stdout);

    fd_set all;
    FD_ZERO(&all);
    FD_SET(server, &all);
    int maxFd = server;
    uint8_t query[MODBUS_TCP_MAX_ADU_LENGTH];
    while (!g_quit) {
        fd_set ready = all;
        if (select(maxFd + 1, &ready, NULL, NULL, NULL) < 0) {
            if (errno == EINTR) continue;
            perror("trilho-modbus-reference: select");
            break;
        }
        for (int fd = 0; fd <= maxFd; ++fd) {
            if (!FD_ISSET(fd, &ready)) continue;
            if (fd == server) {
                /* modbus_tcp_accept also makes the new socket the context's current one. */
                int s = server;
                const int client = modbus_tcp_accept(ctx, &s);
                if (client < 0) continue;
                if (client >= FD_SETSIZE) {
                    close(client);
                    continue;
                }
                FD_SET(client, &all);
                if (client > maxFd) maxFd = client;
                continue;
            }
            modbus_set_socket(ctx, fd);
            const int rc = modbus_receive(ctx, query);
            if (rc > 0) {
                modbus_reply(ctx, query, rc, map);
            } else if (rc < 0) { /* closed or broken: forget the client */
                close(fd);
                FD_CLR(fd, &all);
                while (maxFd > server && !FD_ISSET(maxFd, &all))
                    --maxFd;
            }
        }
    }
    for (int fd = 0; fd <= maxFd; ++fd)
        if (fd != server && FD_ISSET(fd, &all)) close(fd);
    close(server);
    modbus_mapping_free(map);
    modbus_free(ctx);
    printf("trilho-modbus-reference: stopped\n");
    return 0;
}
