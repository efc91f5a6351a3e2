/* Baseline server: one thread echoes every byte back to each of N TCP connections (argument, default
 * 1), waiting on all of them with poll() as the simulator waits on its programs; prints its port
 * first and ends when every connection has closed. */
#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/socket.h>
#include <unistd.h>

#define MAX_CLIENTS 256

int main(int argc, char **argv)
{
    int clients = argc > 1 ? atoi(argv[1]) : 1;
    if (clients < 1 || clients > MAX_CLIENTS)
        return 2;
    int listener = socket(AF_INET, SOCK_STREAM, 0);
    struct sockaddr_in address = {.sin_family = AF_INET, .sin_port = 0};
    inet_pton(AF_INET, "127.0.0.1", &address.sin_addr);
    socklen_t size = sizeof address;
    if (bind(listener, (struct sockaddr *)&address, size) != 0 || listen(listener, clients) != 0)
        return 1;
    getsockname(listener, (struct sockaddr *)&address, &size);
    printf("%d\n", ntohs(address.sin_port));
    fflush(stdout);
    struct pollfd polled[MAX_CLIENTS];
    int one = 1;
    for (int k = 0; k < clients; k++) {
        polled[k].fd = accept(listener, NULL, NULL);
        polled[k].events = POLLIN;
        setsockopt(polled[k].fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    }
    char buffer[4096];
    for (int open = clients; open > 0;) {
        if (poll(polled, (nfds_t)clients, -1) < 0)
            return 1;
        for (int k = 0; k < clients; k++) {
            if (polled[k].fd < 0 || !(polled[k].revents & (POLLIN | POLLHUP | POLLERR)))
                continue;
            ssize_t n = recv(polled[k].fd, buffer, sizeof buffer, 0);
            if (n <= 0) {
                close(polled[k].fd);
                polled[k].fd = -1;
                open--;
            } else if (send(polled[k].fd, buffer, (size_t)n, 0) != n) {
                return 1;
            }
        }
    }
    return 0;
}
