"""Networking: a connected program (session), the I/O thread and the TCP server for RoBIOS programs."""
