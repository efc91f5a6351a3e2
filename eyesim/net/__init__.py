"""Networking: the I/O thread and the TCP server for RoBIOS programs."""
