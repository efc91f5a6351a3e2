/* Baseline client: N round trips of a PSDGet-sized frame to a raw TCP echo server (us per line). */
#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <time.h>
#include <unistd.h>

static double now_us(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec * 1e6 + ts.tv_nsec / 1e3;
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: echo_client PORT CALLS\n");
        return 2;
    }
    int calls = atoi(argv[2]);
    int sock = socket(AF_INET, SOCK_STREAM, 0);
    struct sockaddr_in address = {.sin_family = AF_INET, .sin_port = htons(atoi(argv[1]))};
    inet_pton(AF_INET, "127.0.0.1", &address.sin_addr);
    if (connect(sock, (struct sockaddr *)&address, sizeof address) != 0) {
        perror("connect");
        return 1;
    }
    int one = 1;
    setsockopt(sock, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    unsigned char frame[16] = {12, 0, 0, 0}; /* same size as a PSDGet request */
    unsigned char reply[16];
    for (int i = -50; i < calls; i++) {
        double start = now_us();
        if (send(sock, frame, sizeof frame, 0) != (ssize_t)sizeof frame)
            return 1;
        size_t got = 0;
        while (got < sizeof reply) {
            ssize_t n = recv(sock, reply + got, sizeof reply - got, 0);
            if (n <= 0)
                return 1;
            got += (size_t)n;
        }
        if (i >= 0)
            printf("%.2f\n", now_us() - start);
    }
    close(sock);
    return 0;
}
