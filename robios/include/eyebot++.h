/* eyebot++.h: the RoBIOS-7 API for C++ programs: eyebot.h plus the standard headers C++ labs expect. */
#ifndef EYEBOT_PLUSPLUS_H
#define EYEBOT_PLUSPLUS_H

#ifndef __cplusplus
#error "eyebot++.h is for C++ programs (eyesim c++ prog.cpp); a C program includes eyebot.h"
#endif

/* The C library, also under its C names (printf, sqrt, ...) as older lab code uses them. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <list>
#include <map>
#include <memory>
#include <mutex>
#include <numeric>
#include <queue>
#include <set>
#include <sstream>
#include <stack>
#include <string>
#include <thread>
#include <tuple>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

/* No `using namespace std;`: it would make names students often use for their own variables
 * (distance, count, left, right, ...) ambiguous. Write std::vector, or `using` what you need. */

/* Last, so that its macros (RED, NORMAL, VERSION, ...) cannot collide with the standard headers. */
#include "eyebot.h"

#endif /* EYEBOT_PLUSPLUS_H */
