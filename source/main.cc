#include <ddcontact/version.h>

#include <iostream>

int
main()
{
  std::cout << ddcontact::version_banner() << std::endl;
  return 0;
}
